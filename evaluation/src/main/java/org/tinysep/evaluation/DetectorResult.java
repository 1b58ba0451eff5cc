package org.tinysep.evaluation;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.concurrent.Future;

/** Sums one detector's runs (every fold's test run, every collapse batch) into its {@link Experiment.Result}. */
final class DetectorResult {

    private DetectorResult() {
    }

    /**
     * @param testRuns     the fold's test runs, in fold order
     * @param collapseRuns the collapse batches
     * @param collapseDrops datagrams the kernel dropped in the collapse runs
     */
    static Experiment.Result of(String d, Home home, Split split, long shiftDays,
            List<Future<PlatformRun.Outcome>> testRuns, List<Future<List<CollapseResult>>> collapseRuns,
            long collapseDrops) throws Exception {
        List<TestHalfFigures> parts = new ArrayList<>();
        Timeline first = null;
        PlatformRun.Outcome firstRun = null;
        long mailCount = 0;
        long handed = 0;
        long kernel = 0;
        for (int i = 0; i < split.folds().size(); i++) {
            Split.Fold f = split.folds().get(i);
            PlatformRun.Outcome t = testRuns.get(i).get();
            List<Split.TestSegment> segs = Split.testSegments(home, f);
            Timeline tl = Timeline.of(t.entries(), shiftDays + f.extraDays(),
                    segs.get(0).events().get(0).time().minusSeconds(120));
            parts.add(TestHalfFigures.of(tl, home.labels(), segs.stream().map(Split.TestSegment::judged).toList()));
            if (first == null) {
                first = tl;
                firstRun = t;
            }
            mailCount += t.mails().size();
            handed += t.handedOver();
            kernel = kernel < 0 || t.kernelDrops() < 0 ? -1 : kernel + t.kernelDrops();
        }
        List<CollapseResult> cs = new ArrayList<>();
        for (Future<List<CollapseResult>> f : collapseRuns) {
            cs.addAll(f.get());
        }
        cs.sort(Comparator.comparing(CollapseResult::at));
        return new Experiment.Result(d, TestHalfFigures.sum(parts), first, firstRun, cs, mailCount, handed,
                kernel < 0 ? -1 : kernel + collapseDrops);
    }
}
