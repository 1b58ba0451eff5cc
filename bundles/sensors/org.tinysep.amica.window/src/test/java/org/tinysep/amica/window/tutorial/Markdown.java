package org.tinysep.amica.window.tutorial;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** The parts of a Markdown page the tutorial test needs: fenced code blocks, inline code spans, links, headings. */
final class Markdown {

    /**
     * One fenced code block.
     *
     * @param info the info string after the opening fence, e.g. {@code sh copy}
     * @param body the lines between the fences
     * @param line the 1-based line of the opening fence
     */
    record Block(String info, String body, int line) {

        String language() {
            return info.isBlank() ? "" : info.strip().split("\\s+")[0];
        }

        boolean has(String attribute) {
            String[] words = info.strip().split("\\s+");
            return Arrays.asList(words).subList(Math.min(1, words.length), words.length).contains(attribute);
        }
    }

    private static final Pattern CODE_SPAN = Pattern.compile("`([^`]+)`");
    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s]+)\\)");

    private final List<Block> blocks = new ArrayList<>();
    private final StringBuilder prose = new StringBuilder();
    private final Set<String> headings = new LinkedHashSet<>();

    Markdown(String text) {
        String[] lines = text.split("\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String l = lines[i];
            if (l.startsWith("```")) {
                int start = i;
                StringBuilder body = new StringBuilder();
                for (i++; i < lines.length && !lines[i].startsWith("```"); i++) {
                    body.append(lines[i]).append('\n');
                }
                if (i == lines.length) {
                    throw new IllegalArgumentException("unclosed code block at line " + (start + 1));
                }
                blocks.add(new Block(l.substring(3), body.toString(), start + 1));
                continue;
            }
            if (l.startsWith("#")) {
                headings.add(slug(l.replaceFirst("^#+\\s*", "")));
            }
            prose.append(l).append('\n');
        }
    }

    List<Block> blocks() {
        return blocks;
    }

    /** @return the contents of every inline code span outside code blocks */
    List<String> codeSpans() {
        return all(CODE_SPAN);
    }

    /** @return every link target outside code blocks */
    List<String> links() {
        return all(LINK);
    }

    /** @return the GitHub anchors of every heading */
    Set<String> anchors() {
        return headings;
    }

    private List<String> all(Pattern p) {
        List<String> out = new ArrayList<>();
        Matcher m = p.matcher(prose);
        while (m.find()) {
            out.add(m.group(1));
        }
        return out;
    }

    /** GitHub's heading anchor: lower case, punctuation dropped, spaces to hyphens. */
    static String slug(String heading) {
        return heading.strip().toLowerCase(Locale.ROOT).replaceAll("[^\\p{L}\\p{N} _-]", "").replace(' ', '-');
    }
}
