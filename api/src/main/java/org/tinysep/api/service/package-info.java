/**
 * Intermediate and AAL service interfaces: flat occupancy, house information, mail, time, inactivity recognition.
 * 1.1: the Mail Manager sends to given addresses and tells what became of each message ({@link MailDelivery}).
 * 1.2: Inactivity Recognition watches each wearer of a person node on their own ({@link PersonWatch},
 * {@link InactivityRecognitionProvider#persons()}).
 */
@Export
@Version("1.2.0")
package org.tinysep.api.service;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
