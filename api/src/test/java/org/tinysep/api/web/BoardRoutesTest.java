package org.tinysep.api.web;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;
import java.util.Optional;
import org.junit.jupiter.api.Test;

/** The board's acknowledge route, as the board reads it (below /board) and as the login filter sees it (the URI). */
class BoardRoutesTest {

    @Test
    void theBoardReadsTheFlatAndTheAlertBelowItsRoot() {
        assertEquals(Optional.of(new BoardRoutes.Acknowledge("flat-17", "5")),
                BoardRoutes.acknowledge("/api/flats/flat-17/alerts/5/acknowledge"));
        assertEquals(Optional.empty(), BoardRoutes.acknowledge("/api/flats"));
        assertEquals(Optional.empty(), BoardRoutes.acknowledge(null));
    }

    @Test
    void theLoginFilterKnowsTheSameCallByItsUri() {
        assertTrue(BoardRoutes.isAcknowledge("/board/api/flats/flat-17/alerts/5/acknowledge"));
        for (String uri : List.of("/board/api/flats/flat-17/alerts/5/acknowledge/x",
                "/board/api/flats/flat-17/alerts//acknowledge", "/board/api/flats/a/b/alerts/5/acknowledge",
                "/board/api/flats", "/board/", "/x/board/api/flats/f/alerts/5/acknowledge",
                "/api/flats/f/alerts/5/acknowledge", "/boardx/api/flats/f/alerts/5/acknowledge")) {
            assertFalse(BoardRoutes.isAcknowledge(uri), uri);
        }
        assertEquals(BoardRoutes.ROOT + "/*", BoardRoutes.SERVLET_PATTERN);
    }

    @Test
    void onlyTheLoginPageAndWhatItNeedsArePublic() {
        assertTrue(WebConsole.PUBLIC_PAGES.contains(WebConsole.LOGIN_PAGE));
        assertFalse(WebConsole.PUBLIC_PAGES.contains("/index.html"));
        assertFalse(WebConsole.PUBLIC_PAGES.contains("/board/"));
    }
}
