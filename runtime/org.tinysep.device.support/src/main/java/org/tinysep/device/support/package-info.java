/**
 * Building blocks for TinySEP drivers and devices: safe listener lists, provider tracking, device service
 * registration, the platform clock and log reporting.
 * <p>
 * Application bundles do not import this package at run time: bnd copies the classes they use into each
 * bundle ({@code -conditionalpackage: org.tinysep.device.support}), so an application still depends only on
 * the exported API packages and can be updated on its own.
 */
@Version("1.9.0")
package org.tinysep.device.support;

import org.osgi.annotation.versioning.Version;
