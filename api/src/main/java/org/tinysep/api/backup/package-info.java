/**
 * System backup (thesis 3.7): every driver and device hands its settings to the device manager's
 * {@link org.tinysep.api.backup.BackupStore} as a {@link org.tinysep.api.backup.ComponentBackup}; the store keeps
 * one XML file per component and gives them back to their owners when the platform starts again.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.backup;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
