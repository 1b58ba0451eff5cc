package org.tinysep.api.web;

import java.util.Set;

/**
 * What the web console's bundles agree on: the login filter of {@code org.tinysep.web.api} marks every request it
 * let through with a session ({@link #ROLE_ATTRIBUTE}); the pages ({@code org.tinysep.web.console}) and the central
 * board ({@code org.tinysep.mqtt.board}) serve nothing but the {@link #PUBLIC_PAGES} without that mark.
 */
public final class WebConsole {

    /**
     * Request attribute set by the login filter on a request with a session: the role's name ({@code installer} or
     * {@code caregiver}). Absent means the login filter did not run (its bundle is stopped): refuse.
     */
    public static final String ROLE_ATTRIBUTE = "org.tinysep.web.role";

    /** Where a request without a session is sent. */
    public static final String LOGIN_PAGE = "/login.html";

    /** What may be fetched before logging in: the login page and what it needs. */
    public static final Set<String> PUBLIC_PAGES = Set.of(LOGIN_PAGE, "/login.js", "/console.css", "/favicon.svg");

    private WebConsole() {
    }
}
