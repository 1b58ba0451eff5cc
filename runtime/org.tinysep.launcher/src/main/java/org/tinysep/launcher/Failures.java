package org.tinysep.launcher;

import java.util.regex.Pattern;
import org.osgi.framework.BundleException;

/** Turns bundle start and resolution errors into one readable line (no stack trace). */
public final class Failures {

    /** {@code [org.x [12](R 12.0)] } as Felix puts it before each requirement. */
    private static final Pattern BRACKETED_REF = Pattern.compile("\\[[^\\[\\]]+ \\[\\d+\\]\\(R [\\d.]+\\)\\] ");
    /** {@code  [12](R 12.0)} after a symbolic name. */
    private static final Pattern INLINE_REF = Pattern.compile(" \\[\\d+\\]\\(R [\\d.]+\\)");
    private static final Pattern LEADING_UNABLE = Pattern.compile("^Unable to resolve [^:]+: ");

    private Failures() {
    }

    /**
     * @return a one-line description: for a resolution error the first missing requirement chain, for an
     *         activator error the root cause's type and message
     */
    public static String describe(Throwable t) {
        if (t instanceof BundleException be && be.getType() == BundleException.RESOLVE_ERROR) {
            return shortenResolution(String.valueOf(be.getMessage()));
        }
        Throwable root = t;
        while (root.getCause() != null && root.getCause() != root) {
            root = root.getCause();
        }
        String text = root.getClass().getSimpleName() + (root.getMessage() == null ? "" : ": " + root.getMessage());
        return root == t ? text : String.valueOf(t.getMessage()) + " caused by " + text;
    }

    /** Shortens Felix's "Unable to resolve …: missing requirement …" message. */
    static String shortenResolution(String message) {
        String s = message;
        int cut = s.indexOf(" Unresolved requirements:");
        if (cut > 0) {
            s = s.substring(0, cut);
        }
        s = BRACKETED_REF.matcher(s).replaceAll("");
        s = INLINE_REF.matcher(s).replaceAll("");
        s = LEADING_UNABLE.matcher(s).replaceFirst("");
        return s.replaceAll("\\s+", " ").trim();
    }
}
