/**
 * Intermediate and AAL service interfaces: flat occupancy, house information, mail, time, inactivity recognition.
 * 1.1: the Mail Manager sends to given addresses and tells what became of each message ({@link MailDelivery}).
 */
@Export
@Version("1.1.0")
package org.tinysep.api.service;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
