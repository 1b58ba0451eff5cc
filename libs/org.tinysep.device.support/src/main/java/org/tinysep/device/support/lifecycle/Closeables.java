package org.tinysep.device.support.lifecycle;

/**
 * Closing the optional parts of a driver or a link in order, written once: a driver's deactivation
 * ({@link AbstractDriver#stop(AutoCloseable...)}), the Sun SPOT bus radio's links.
 */
public final class Closeables {

    private Closeables() {
    }

    /**
     * Closes the parts in the order given; null ones (never opened) are skipped. A part that throws stops there, as
     * a close written out by hand would: a runtime exception as it is, a checked one as an
     * {@link IllegalStateException}.
     *
     * @param owner what the parts belong to, for the message, e.g. a driver's name
     */
    public static void closeInOrder(Object owner, AutoCloseable... parts) {
        for (AutoCloseable part : parts) {
            if (part != null) {
                try {
                    part.close();
                } catch (RuntimeException e) {
                    throw e;
                } catch (Exception e) {
                    throw new IllegalStateException(owner + ": cannot close " + part + ": " + e.getMessage(), e);
                }
            }
        }
    }
}
