/**
 * The web console's shared names in one place: the request attribute the login filter sets, the pages open before
 * logging in ({@link org.tinysep.api.web.WebConsole}) and the central board's routes
 * ({@link org.tinysep.api.web.BoardRoutes}). Used by {@code org.tinysep.web.api}, {@code org.tinysep.web.console} and
 * {@code org.tinysep.mqtt.board}.
 */
@Export
@Version("1.0.0")
package org.tinysep.api.web;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
