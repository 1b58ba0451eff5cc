package org.tinysep.evaluation;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/** Puts a home's table into the README between {@code <!-- results:<home> -->} and {@code <!-- /results:<home> -->}. */
final class Readme {

    private Readme() {
    }

    static void put(Path readme, String home, String markdown) throws IOException {
        String begin = "<!-- results:" + home + " -->";
        String end = "<!-- /results:" + home + " -->";
        String text = Files.isRegularFile(readme) ? Files.readString(readme) : "";
        String block = begin + "\n" + markdown + end;
        int a = text.indexOf(begin);
        int b = text.indexOf(end);
        text = a >= 0 && b > a ? text.substring(0, a) + block + text.substring(b + end.length())
                : text + (text.endsWith("\n") || text.isEmpty() ? "" : "\n") + "\n" + block + "\n";
        Path tmp = readme.resolveSibling(readme.getFileName() + ".tmp");
        Files.writeString(tmp, text);
        Files.move(tmp, readme, StandardCopyOption.REPLACE_EXISTING, StandardCopyOption.ATOMIC_MOVE);
    }
}
