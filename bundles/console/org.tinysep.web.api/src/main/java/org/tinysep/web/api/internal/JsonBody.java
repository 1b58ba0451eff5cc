package org.tinysep.web.api.internal;

import java.util.Map;
import org.tinysep.json.JsonException;
import org.tinysep.json.JsonReader;

/**
 * Reads a request body that must be one flat JSON object whose values are strings, numbers, booleans or null
 * (e.g. {@code {"value":"Kitchen"}}): every value comes back as text (null as absent), read strictly by the shared
 * {@link JsonReader}. Anything else is an {@link ApiException} 400 that says what is wrong and at which character.
 */
public final class JsonBody {

    private JsonBody() {
    }

    /** @return the object's members, in order */
    public static Map<String, String> parse(String text) {
        try {
            return JsonReader.flatObject(text, ApiServlet.MAX_BODY);
        } catch (JsonException e) {
            throw ApiException.badRequest("the request body is " + e.getMessage());
        }
    }
}
