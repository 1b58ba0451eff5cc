package org.tinysep.simulator.replay;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Converter from the Ordonez files of one home to the generic {@code events.csv} and {@code labels.csv}:
 * {@code java -cp <simulator jar>:<amica protocol jar> org.tinysep.simulator.replay.ConvertOrdonez
 * <ordonez dir> <A|B> <output dir>}.
 */
public final class ConvertOrdonez {

    private ConvertOrdonez() {
    }

    /**
     * @param dataDir folder holding {@code Ordonez<home>_Sensors.txt} and {@code Ordonez<home>_ADLs.txt}
     * @param home    {@code A} or {@code B}
     * @param outDir  folder to write {@code events.csv} and {@code labels.csv} into (created if missing)
     * @return a one-line summary, e.g. {@code 818 events, 248 labels}
     * @throws IOException if reading or writing fails
     * @throws ReplayFormatException if an input file is malformed
     */
    public static String convert(Path dataDir, String home, Path outDir) throws IOException, ReplayFormatException {
        List<SensorEvent> events = OrdonezReader.readSensors(dataDir.resolve("Ordonez" + home + "_Sensors.txt"));
        List<Label> labels = OrdonezReader.readLabels(dataDir.resolve("Ordonez" + home + "_ADLs.txt"));
        Files.createDirectories(outDir);
        EventsCsv.write(events, outDir.resolve("events.csv"));
        LabelsCsv.write(labels, outDir.resolve("labels.csv"));
        return events.size() + " events, " + labels.size() + " labels";
    }

    /**
     * Command line entry.
     *
     * @param args ordonez dir, home letter, output dir
     */
    public static void main(String[] args) {
        if (args.length != 3) {
            System.err.println("usage: ConvertOrdonez <ordonez dir> <A|B> <output dir>");
            System.exit(2);
        }
        try {
            System.out.println(convert(Path.of(args[0]), args[1], Path.of(args[2])) + " written to " + args[2]);
        } catch (java.nio.file.NoSuchFileException e) {
            System.err.println("cannot convert: no such file " + e.getFile());
            System.exit(1);
        } catch (IOException | ReplayFormatException e) {
            System.err.println("cannot convert: " + e.getMessage());
            System.exit(1);
        }
    }
}
