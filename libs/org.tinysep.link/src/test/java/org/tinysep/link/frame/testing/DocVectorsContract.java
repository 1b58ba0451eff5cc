package org.tinysep.link.frame.testing;

import java.io.IOException;
import java.util.List;
import java.util.Map;
import org.junit.jupiter.api.Test;

/**
 * The doc-vector test of a protocol family, written once: a family's test extends this class with its document and
 * codecs, states the frame of a vector's {@code frame} line and its own payload checks ({@link DocVectors.Family}),
 * and keeps only its own tests (which vectors the document must have, the stream of all of them).
 *
 * @param <F> the frame
 * @param <P> the payload
 */
public abstract class DocVectorsContract<F, P> implements DocVectors.Family<F, P> {

    private final String doc;
    private final Codecs<F, P, ?> codecs;

    /** @param doc the document's file name under {@code docs/protocols/}, e.g. {@code "amica.md"} */
    protected DocVectorsContract(String doc, Codecs<F, P, ?> codecs) {
        this.doc = doc;
        this.codecs = codecs;
    }

    /** @return every vector of the document: a map of key to value per vector, in document order */
    protected final List<Map<String, String>> vectors() throws IOException {
        return DocVectors.read(doc);
    }

    @Test
    void everyVectorDecodesAndEncodesAsDocumented() throws Exception {
        DocVectors.check(vectors(), codecs, this);
    }
}
