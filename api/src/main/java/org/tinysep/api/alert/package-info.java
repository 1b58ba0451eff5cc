/**
 * Alerts a caregiver can trust: an alert stays open until someone acknowledges it or its cause ends, is repeated and
 * escalated along a contact list while nobody does, and every step of it is kept. The shell, the web console and an
 * MQTT bridge all use {@link org.tinysep.api.alert.AlertService}.
 * 1.1: alert kinds HELP and FALL (the person node).
 * 1.2: {@link org.tinysep.api.alert.Notification#channel()}: which channel (mail, SMS, push) reached whom.
 * 1.3: {@link org.tinysep.api.alert.AlertKind#words()}: a kind in the plain words every view shows.
 */
@Export
@Version("1.3.0")
package org.tinysep.api.alert;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
