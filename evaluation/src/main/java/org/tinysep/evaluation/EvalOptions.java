package org.tinysep.evaluation;

import java.nio.file.Path;
import java.util.List;
import org.tinysep.tools.cli.Cli;

/**
 * The command line of {@link Evaluate}, parsed and checked ({@link EvalFlags}).
 *
 * @param home        {@code A}, {@code B} (Ordonez) or a folder with events.csv and labels.csv
 * @param collapses   injected collapses per detector
 * @param seed        seed of the collapse draw
 * @param warmupHours replayed before each collapse (at least; see README)
 * @param parallel    platform processes at once
 * @param batch       collapses replayed one after another by one platform process (each in its own virtual weeks)
 * @param days        use only the first N days of the recording (0 = all): the smoke test's short window
 * @param detectors   values of Inactivity Recognition's {@code detector} key, side by side
 * @param ordonez     folder of the Ordonez files
 * @param dist        the assembled distribution (runtime/org.tinysep.launcher/target/tinysep)
 * @param work        folder for state folders and converted files
 * @param readme      README to write the table into (null: print only)
 * @param command     the command line as typed, for the report
 * @param split       {@code half} (history = first half, the headline) or {@code cvK} (K folds by days, {@link Split})
 * @param words       which labelled activities mean away and asleep
 */
record EvalOptions(String home, int collapses, long seed, int warmupHours, int parallel, int batch, int days,
        List<String> detectors, Path ordonez, Path dist, Path work, Path readme, String command, String split,
        LabelWords words, Integer residents) {

    /**
     * @param args the command line ({@link EvalFlags}: every option, its default and its check)
     * @param repo the repository, which the default folders are in
     * @throws IllegalArgumentException naming an unknown option, a bad value or a stray argument
     */
    static EvalOptions parse(String[] args, Path repo) {
        return Cli.parse(new EvalFlags(), args).options(repo, "./evaluate.sh " + String.join(" ", args));
    }
}
