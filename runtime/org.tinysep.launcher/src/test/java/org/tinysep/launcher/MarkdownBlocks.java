package org.tinysep.launcher;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/** The fenced code blocks and the text of one section of a Markdown page, as a reader sees them. */
final class MarkdownBlocks {

    /** One fenced block: its info string ({@code sh}, or empty for shell transcripts) and its lines. */
    record Block(String info, List<String> lines) {

        /** @return the block's commands: lines joined across a trailing {@code \}, blank lines left out */
        List<String> commands() {
            List<String> out = new ArrayList<>();
            StringBuilder current = new StringBuilder();
            for (String line : lines) {
                if (line.endsWith("\\")) {
                    current.append(line, 0, line.length() - 1);
                    continue;
                }
                current.append(line);
                if (!current.toString().isBlank()) {
                    out.add(current.toString().strip().replaceAll("\\s+", " "));
                }
                current.setLength(0);
            }
            return out;
        }
    }

    private final String text;
    private final List<Block> blocks;

    private MarkdownBlocks(String text, List<Block> blocks) {
        this.text = text;
        this.blocks = blocks;
    }

    /** @param heading the section's heading line, e.g. {@code ## Try it in one minute}; the section ends at the next of its level */
    static MarkdownBlocks section(Path page, String heading) throws IOException {
        List<String> lines = Files.readAllLines(page);
        int start = lines.indexOf(heading);
        if (start < 0) {
            throw new AssertionError(page + " has no section '" + heading + "'");
        }
        String level = heading.substring(0, heading.indexOf(' ') + 1);
        List<String> section = new ArrayList<>();
        List<Block> blocks = new ArrayList<>();
        List<String> block = null;
        String info = null;
        for (int i = start + 1; i < lines.size(); i++) {
            String line = lines.get(i);
            if (block == null && line.startsWith(level)) {
                break;
            }
            section.add(line);
            if (line.startsWith("```")) {
                if (block == null) {
                    block = new ArrayList<>();
                    info = line.substring(3).strip();
                } else {
                    blocks.add(new Block(info, List.copyOf(block)));
                    block = null;
                }
            } else if (block != null) {
                block.add(line);
            }
        }
        return new MarkdownBlocks(String.join("\n", section), List.copyOf(blocks));
    }

    List<Block> blocks() {
        return blocks;
    }

    String text() {
        return text;
    }

    /** @return the inline code spans ({@code `…`}) of the paragraph that starts with {@code start} */
    List<String> codeSpansOfParagraph(String start) {
        int at = text.indexOf(start);
        if (at < 0) {
            throw new AssertionError("no paragraph starting with '" + start + "'");
        }
        int end = text.indexOf("\n\n", at);
        String paragraph = text.substring(at, end < 0 ? text.length() : end);
        List<String> spans = new ArrayList<>();
        Matcher m = Pattern.compile("`([^`]+)`").matcher(paragraph);
        while (m.find()) {
            spans.add(m.group(1));
        }
        return spans;
    }

    /**
     * @return whether every non-ellipsis line of {@code expected} matches a line of {@code actual}, in order;
     *         {@code …} stands for any text and runs of blanks for any blanks (table columns pad differently)
     */
    static boolean shows(List<String> expected, String actual) {
        List<String> lines = actual.lines().map(l -> l.strip().replaceAll("\\s+", " ")).toList();
        int next = 0;
        for (String e : expected) {
            String want = e.strip().replaceAll("\\s+", " ");
            if (want.isEmpty() || want.equals("…")) {
                continue;
            }
            String[] parts = want.split("…", -1);
            StringBuilder regex = new StringBuilder(Pattern.quote(parts[0]));
            for (int i = 1; i < parts.length; i++) {
                regex.append(".*").append(Pattern.quote(parts[i]));
            }
            Pattern p = Pattern.compile(regex.toString());
            while (next < lines.size() && !p.matcher(lines.get(next)).matches()) {
                next++;
            }
            if (next == lines.size()) {
                return false;
            }
            next++;
        }
        return true;
    }
}
