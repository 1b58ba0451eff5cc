package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import java.time.Instant;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;
import org.tinysep.api.backup.ComponentKind;

/**
 * The hand-written backup writer gives the very bytes of JAXB's formatted output, so files written before and
 * after it are alike and JAXB (which reads them) reads back the same backup.
 */
class BackupXmlWriterTest {

    private static final String CHARS = "aZ09 .-_&<>\"'\t\n\r/=;:äöüß€\u00e9\u4e2d\uD83D\uDE00]]>?!#%";

    private static String text(Random r, int max) {
        StringBuilder s = new StringBuilder();
        int n = r.nextInt(max + 1);
        for (int i = 0; i < n; i++) {
            int at = r.nextInt(CHARS.length());
            char c = CHARS.charAt(at);
            if (Character.isHighSurrogate(c) || Character.isLowSurrogate(c)) {
                s.append("\uD83D\uDE00"); // a whole pair, never half of one
            } else {
                s.append(c);
            }
        }
        return s.toString();
    }

    static ComponentBackup random(Random r) {
        Map<String, String> parameters = new LinkedHashMap<>();
        Map<String, String> state = new LinkedHashMap<>();
        for (int i = r.nextInt(4); i > 0; i--) {
            parameters.put("k" + i + text(r, 5), text(r, 12));
        }
        for (int i = r.nextInt(4); i > 0; i--) {
            state.put("s" + i + text(r, 5), text(r, 12));
        }
        List<String> types = new ArrayList<>();
        for (int i = r.nextInt(3); i > 0; i--) {
            types.add(text(r, 8));
        }
        return new ComponentBackup("uid-" + text(r, 10), r.nextBoolean() ? ComponentKind.DEVICE : ComponentKind.DRIVER,
                text(r, 10), text(r, 10), text(r, 10), text(r, 16), parameters, text(r, 6), types,
                r.nextBoolean() ? null : Instant.ofEpochSecond(1_700_000_000L + r.nextInt(1_000_000), r.nextInt(999_999_999)),
                state, Instant.ofEpochSecond(1_700_000_000L + r.nextInt(1_000_000), r.nextInt(999_999_999)));
    }

    @Test
    void aPlainBackupReadsBackTheSame() throws Exception {
        ComponentBackup b = new ComponentBackup("dev-1", ComponentKind.DEVICE, "drv", "AmicaMovement", "AmicaMovement",
                "Kitchen <motion> & \"door\"", Map.of("room", "r-1"), "1.20", List.of("movement"),
                Instant.parse("2026-11-29T10:00:00.123Z"), Map.of("battery", "3000"),
                Instant.parse("2026-11-29T10:00:01Z"));
        assertEquals(b, new BackupCodec().read(BackupXmlWriter.write(b)));
    }

    @Test
    void writesTheBytesJaxbWrites() throws Exception {
        BackupCodec codec = new BackupCodec();
        Random r = new Random(29);
        for (int i = 0; i < 500; i++) {
            ComponentBackup b = random(r);
            byte[] ours = BackupXmlWriter.write(b);
            assertEquals(new String(codec.writeWithJaxb(b), StandardCharsets.UTF_8),
                    new String(ours, StandardCharsets.UTF_8), "backup " + i);
            codec.read(ours); // well-formed: JAXB reads it (values keep XML's line-end and attribute rules)
        }
    }
}
