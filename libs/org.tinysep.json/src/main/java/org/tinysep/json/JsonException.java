package org.tinysep.json;

/**
 * Text that is not the JSON asked for. The message says what is wrong and where, e.g.
 * {@code not valid JSON: ',' or '}' expected at character 12}; callers put their subject in front
 * ({@code "the payload is " + e.getMessage()}).
 */
public final class JsonException extends IllegalArgumentException {

    private static final long serialVersionUID = 1L;

    private final int position;

    JsonException(String message, int position) {
        super(position > 0 ? message + " at character " + position : message);
        this.position = position;
    }

    /** @return the 1-based character where the text goes wrong, or 0 when the whole text is refused (too long) */
    public int position() {
        return position;
    }
}
