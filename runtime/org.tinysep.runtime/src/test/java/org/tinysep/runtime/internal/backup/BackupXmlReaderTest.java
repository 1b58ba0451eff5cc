package org.tinysep.runtime.internal.backup;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotNull;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.nio.charset.StandardCharsets;
import java.util.Random;
import org.junit.jupiter.api.Test;
import org.tinysep.api.backup.ComponentBackup;

/**
 * The reader without JAXB takes every file the writer writes and reads it as JAXB does; a file outside that shape
 * (damaged, edited, another writer's) it declines, and JAXB reads it as before. Compared on random backups and on
 * thousands of damaged copies: both readers give the same backup or both refuse the file.
 */
class BackupXmlReaderTest {

    private final BackupCodec codec = new BackupCodec();

    /** @return the backup read, or "refused" */
    private static Object outcome(ThrowingRead read) {
        try {
            return read.read();
        } catch (BadBackupException e) {
            return "refused";
        }
    }

    private interface ThrowingRead {
        ComponentBackup read() throws BadBackupException;
    }

    @Test
    void readsEveryFileTheWriterWritesAsJaxbDoes() throws Exception {
        Random r = new Random(4);
        for (int i = 0; i < 500; i++) {
            byte[] file = BackupXmlWriter.write(BackupXmlWriterTest.random(r));
            assertNotNull(BackupXmlReader.read(file), "the writer's file " + i + " is read without JAXB");
            assertEquals(outcome(() -> codec.readWithJaxb(file)), outcome(() -> codec.read(file)), "file " + i);
        }
    }

    @Test
    void damagedFilesGetTheSameAnswerAsFromJaxb() {
        Random r = new Random(29);
        String[] bits = {"<", ">", "&", "\"", "'", "=", "/", ";", "x", "\r", "\u0000", " ", "<!-- c -->", "&#0;",
            "&#x41;", "&bogus;", "]]>", "<uid>2</uid>", "<extra/>", "\n", "\t", "&#10;", "<![CDATA[a]]>"};
        int declined = 0;
        for (int i = 0; i < 2_000; i++) {
            String good = new String(BackupXmlWriter.write(BackupXmlWriterTest.random(r)), StandardCharsets.UTF_8);
            int at = r.nextInt(good.length() + 1);
            String bad = switch (r.nextInt(4)) {
                case 0 -> good.substring(0, at); // cut short (a crash while writing)
                case 1 -> good.substring(0, at) + bits[r.nextInt(bits.length)] + good.substring(at);
                case 2 -> at < good.length() ? good.substring(0, at) + bits[r.nextInt(bits.length)]
                        + good.substring(at + 1) : good + "x";
                default -> good.substring(0, at) + good.substring(Math.min(good.length(), at + 1 + r.nextInt(20)));
            };
            byte[] file = bad.getBytes(StandardCharsets.UTF_8);
            if (BackupXmlReader.read(file) == null) {
                declined++;
            }
            assertEquals(outcome(() -> codec.readWithJaxb(file)), outcome(() -> codec.read(file)),
                    "damaged file " + i + ":\n" + bad);
        }
        assertTrue(declined > 600, "most damaged files go to JAXB: " + declined);
    }

    @Test
    void aDocumentTypeOrBytesThatAreNotUtf8AreLeftToJaxb() {
        String good = new String(BackupXmlWriter.write(BackupXmlWriterTest.random(new Random(1))),
                StandardCharsets.UTF_8);
        String dtd = good.replace("?>\n", "?>\n<!DOCTYPE backup [<!ENTITY x \"y\">]>\n");
        assertNull(BackupXmlReader.read(dtd.getBytes(StandardCharsets.UTF_8)));
        byte[] latin = good.getBytes(StandardCharsets.UTF_8);
        latin[latin.length - 3] = (byte) 0xE9;
        assertNull(BackupXmlReader.read(latin));
    }
}
