/**
 * Ways other than e-mail to reach a caregiver: a {@link org.tinysep.api.channel.MessageChannel} per
 * kind of address (SMS through a GSM modem, push), used by the alert service along each contact's ordered list of
 * channels, and a {@link org.tinysep.api.channel.ReplyHandler} that hears replies from phones ("OK 3").
 */
@Export
@Version("1.0.0")
package org.tinysep.api.channel;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
