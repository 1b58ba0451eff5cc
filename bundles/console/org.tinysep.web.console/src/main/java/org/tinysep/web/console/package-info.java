/**
 * The web console's pages, served from this bundle's {@code /web/} folder. Everything lives in
 * {@code org.tinysep.web.console.internal}; the bundle exports nothing.
 */
package org.tinysep.web.console;
