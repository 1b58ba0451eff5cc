package org.tinysep.sms.internal;

/**
 * How a text fits SMS (3GPP TS 23.038): in the GSM 7-bit default alphabet 160 characters in one SMS or 153 per part
 * of a longer one (characters of the extension table count twice); otherwise UCS-2 with 70, or 67 per part.
 * gammu-smsd ({@code TransmitFormat = auto}) makes the same choice when it sends.
 */
final class SmsText {

    /** The GSM 7-bit default alphabet (basic character set), without the escape. */
    private static final String BASIC = "@£$¥èéùìòÇ\nØø\rÅåΔ_ΦΓΛΩΠΨΣΘΞÆæßÉ !\"#¤%&'()*+,-./0123456789:;<=>?"
            + "¡ABCDEFGHIJKLMNOPQRSTUVWXYZÄÖÑÜ§¿abcdefghijklmnopqrstuvwxyzäöñüà";
    /** The extension table: each takes an escape and itself. */
    private static final String EXTENDED = "^{}\\[~]|€\f";

    private SmsText() {
    }

    /** @return whether the whole text can go in the GSM 7-bit alphabet */
    static boolean gsm(String text) {
        return text.chars().allMatch(c -> BASIC.indexOf(c) >= 0 || EXTENDED.indexOf(c) >= 0);
    }

    /** @return the 7-bit septets, or the UCS-2 characters, the text takes */
    static int units(String text) {
        if (!gsm(text)) {
            return text.length();
        }
        return text.length() + (int) text.chars().filter(c -> EXTENDED.indexOf(c) >= 0).count();
    }

    /** @return how many SMS the text takes */
    static int parts(String text) {
        boolean gsm = gsm(text);
        int units = units(text);
        int single = gsm ? 160 : 70;
        int part = gsm ? 153 : 67;
        return units <= single ? 1 : (units + part - 1) / part;
    }

    /**
     * @return {@code title} and {@code tail} on two lines, the title shortened (ending in "...") so that the whole
     *         takes at most {@code maxParts} SMS; the tail (how to answer) is kept whole
     */
    static String fit(String title, String tail, int maxParts) {
        String whole = tail.isEmpty() ? title : title + "\n" + tail;
        if (parts(whole) <= maxParts) {
            return whole;
        }
        String t = title;
        while (!t.isEmpty()) {
            t = t.substring(0, t.length() - 1).stripTrailing();
            String s = (t + "...") + (tail.isEmpty() ? "" : "\n" + tail);
            if (parts(s) <= maxParts) {
                return s;
            }
        }
        String s = tail;
        while (parts(s) > maxParts) {
            s = s.substring(0, s.length() - 1);
        }
        return s;
    }
}
