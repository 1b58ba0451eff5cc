package org.tinysep.evaluation;

import java.nio.file.Path;
import java.time.Duration;
import java.time.Instant;
import java.time.LocalDateTime;
import java.time.ZoneOffset;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import org.tinysep.tools.cli.Cli;

/**
 * Analysis and sweeps on the detector core ({@link CoreReplay}), in seconds instead of the platform's minutes:
 * {@code java ... CoreSweep A|B|folder [half|cv K] [collapses]}. Prints every false alarm (room, hour, limit, why)
 * and every collapse that is not detected, then the figures. Not the published figures (those come from
 * {@link Evaluate}, through the platform). Collapses are judged by {@link CoreCollapses}, the table is {@link CoreTable}.
 */
public final class CoreSweep {

    /** {@code -Dverbose=true}: every false alarm, collapse alerted before it happened, and missed collapse. */
    static final boolean VERBOSE = Boolean.getBoolean("verbose");

    private CoreSweep() {
    }

    /** One home, collapse model and detector: the figures of the summary table. */
    record Figures(String home, String model, boolean learned, double faDay, double faNight, Long medianDay,
            Long medianNight, Long p95, double detected, int collapses, double blind) {
    }

    /**
     * {@code CoreSweep [--model uniform|moving|both] [--split half|cvK] [--collapses N] HOME...}, HOME = A, B, a
     * folder, or a derived home {@code A:nomotion}, {@code B:two} ({@link Variants}); the old form
     * {@code CoreSweep A [half|cv K] [N]} still works. Prints one block per home, model and detector, then a
     * markdown table of all and a summary row (worst and median home).
     */
    public static void main(String[] args) {
        CoreSweepFlags flags = new CoreSweepFlags();
        System.exit(Cli.main(flags, args, System.out, System.err, () -> {
            sweep(flags, args);
            return Cli.OK;
        }));
    }

    private static void sweep(CoreSweepFlags flags, String[] args) throws Exception {
        Path repo = Path.of(System.getProperty("tinysep.repo", "."));
        CoreSweepFlags.Plan plan = flags.plan();
        List<String> homes = plan.homes();
        List<Collapses.Model> models = flags.models;
        int k = plan.folds();
        int n = plan.collapses();
        boolean readme = flags.writeReadme(); // a sweep (-Dfloor=...) must not overwrite the published tables
        String commit = Evaluate.commit(); // at the start: the code that runs
        Instant started = Instant.now().truncatedTo(java.time.temporal.ChronoUnit.SECONDS);
        List<Figures> all = new ArrayList<>();
        for (String spec : homes) {
            Home home = flags.residents == null ? load(spec, repo) : load(spec, repo).withResidents(flags.residents);
            for (Collapses.Model m : models) {
                for (boolean learned : new boolean[] {true, false}) {
                    System.out.println("=== " + home.name() + " " + (learned ? "LEARNED" : "THESIS") + " model "
                            + m.name().toLowerCase(java.util.Locale.ROOT) + " split " + (k > 0 ? "cv" + k : "half"));
                    all.add(report(home, learned, k, n, m));
                }
            }
        }
        String table = CoreTable.facts(started, commit, args, k, n) + "\n" + CoreTable.markdown(all);
        System.out.println();
        System.out.println(table);
        if (readme) { // one command writes the tables of both READMEs
            Readme.put(repo.resolve("evaluation/README.md"), "core", table);
            Readme.put(repo.resolve("README.md"), "core", table);
            System.out.println("written between the results:core markers of README.md and evaluation/README.md");
        }
    }

    /** A, B, a folder, or {@code <home>:<variant>} (variant nomotion or two; the other home is the other Ordonez). */
    static Home load(String spec, Path repo) throws Exception {
        String[] p = spec.split(":", 2);
        Path ordonez = repo.resolve("data/ordonez");
        Path work = repo.resolve("evaluation/target/core");
        Home home = Home.load(p[0], ordonez, work);
        String variant = p.length > 1 ? p[1] : System.getProperty("variant", "");
        if (variant.isEmpty()) {
            return home;
        }
        if (!variant.equals("nomotion") && !variant.equals("two")) {
            throw new IllegalArgumentException("unknown derived home '" + variant + "' in " + spec
                    + ": nomotion (motion sensors dropped) or two (a second resident)");
        }
        Home other = Home.load(p[0].equalsIgnoreCase("A") ? "B" : "A", ordonez, work);
        return Variants.apply(variant, home, other);
    }

    static Figures report(Home home, boolean learned, int k, int n, Collapses.Model model) {
        CoreReplay core = new CoreReplay(home, learned);
        List<List<CoreFold>> folds = new ArrayList<>();
        folds.add(k == 0 ? List.of(CoreFold.half(home)) : CoreFold.cv(home, k));
        int fa = 0;
        int faNight = 0;
        double days = 0;
        Map<String, Integer> faRooms = new TreeMap<>();
        CoreCollapses tally = new CoreCollapses(VERBOSE);
        List<CoreReplay.Act> everything = core.acts(home.events());
        for (CoreFold f : folds.get(0)) {
            List<CoreReplay.Act> hist = core.acts(f.history());
            List<CoreReplay.Act> test = core.acts(f.test());
            if (f.cv()) { // each test day ends with the recording's next activity (the next day's first)
                List<CoreReplay.Act> t = new ArrayList<>();
                for (int i = 0; i < everything.size(); i++) {
                    CoreReplay.Act a = everything.get(i);
                    boolean in = f.judged(a.at());
                    boolean prevIn = i > 0 && f.judged(everything.get(i - 1).at());
                    if (in || prevIn) {
                        t.add(a);
                    }
                }
                test = t;
            }
            days += f.days();
            var lim = core.newLimits();
            core.play(lim, hist, t -> false);
            if (learned) { // how the history made the home's residents (TwoAtOnce): declared or recognised
                System.out.println("  residents after the history: " + (home.residents() > 0
                        ? home.residents() + " declared" : lim.residents().words()));
            }
            for (CoreReplay.Alert a : core.play(lim, test, f::judged)) {
                int h = a.at().atZone(ZoneOffset.UTC).getHour();
                boolean night = h < 7 || h >= 22;
                fa++;
                faNight += night ? 1 : 0;
                faRooms.merge(a.after().room() + (night ? " night" : " day"), 1, Integer::sum);
                if (VERBOSE) {
                    System.out.printf("  FA %s %s after %s, limit %s, quiet %s; %s%n", a.at(), a.after().room(),
                            a.after().what(), a.limit(), gapAfter(test, a.after()), a.why());
                }
            }
            int share = (int) Math.round(n * f.share());
            List<LocalDateTime> moments = model == Collapses.Model.UNIFORM
                    ? Collapses.draw(f.candidates(home), Math.max(1, share), 1)
                    : Collapses.drawAtActivities(everything.stream()
                            .filter(x -> !x.what().startsWith("second resident's"))
                            .map(x -> LocalDateTime.ofInstant(x.at(), ZoneOffset.UTC)).toList(),
                            f.candidates(home), Math.max(1, share), 1);
            for (LocalDateTime c : moments) {
                tally.judge(core, everything, hist, f.cv(), c);
            }
        }
        int total = tally.total();
        System.out.printf("  false alarms / 30 days: day %.1f night %.1f (%d in %.1f days) by room %s%n",
                (fa - faNight) * 30 / days, faNight * 30 / days, fa, days, faRooms);
        System.out.println("  " + tally);
        return new Figures(home.name(), model.name().toLowerCase(java.util.Locale.ROOT), learned,
                (fa - faNight) * 30 / days, faNight * 30 / days, tally.medianDay(), tally.medianNight(), tally.p95(),
                tally.detectedShare(), total, tally.blindShare());
    }

    private static String gapAfter(List<CoreReplay.Act> acts, CoreReplay.Act a) {
        int i = acts.indexOf(a);
        return i + 1 < acts.size() ? Duration.between(a.at(), acts.get(i + 1).at()).toString() : "(end)";
    }
}
