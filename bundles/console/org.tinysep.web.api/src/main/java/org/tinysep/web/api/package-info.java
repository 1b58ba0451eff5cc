/**
 * The web console's REST + Server-Sent Events API. Everything lives in {@code org.tinysep.web.api.internal};
 * the bundle exports nothing: its contract is the HTTP API documented in {@code docs/web-api.md}.
 */
package org.tinysep.web.api;
