package org.tinysep.testsupport.repo;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.FileVisitResult;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.SimpleFileVisitor;
import java.nio.file.attribute.BasicFileAttributes;
import java.util.ArrayList;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.Test;

/**
 * Every relative link of every Markdown page in the repository ({@code [text](path)}, {@code ![image](path)}) leads
 * to a file or folder that exists: a module moved to another folder, or a page renamed, fails the build naming the
 * page, its line and the link. Links to the web ({@code https:}, {@code mailto:}) and in-page anchors are not
 * followed; build output, Git's own folder and page templates under {@code src/main/resources} are not read.
 */
class MarkdownLinksTest {

    private static final Pattern LINK = Pattern.compile("\\]\\(([^)\\s#]+)(#[^)\\s]*)?\\)");

    @Test
    void everyRelativeLinkInThePagesLeadsToAFileOfTheRepository() throws IOException {
        Path root = RepoFiles.root();
        List<Path> pages = new ArrayList<>();
        Files.walkFileTree(root, new SimpleFileVisitor<>() {
            @Override
            public FileVisitResult preVisitDirectory(Path dir, BasicFileAttributes attrs) {
                return !dir.equals(root) && skipped(root.relativize(dir)) ? FileVisitResult.SKIP_SUBTREE
                        : FileVisitResult.CONTINUE;
            }

            @Override
            public FileVisitResult visitFile(Path file, BasicFileAttributes attrs) {
                if (file.getFileName().toString().endsWith(".md")) {
                    pages.add(file);
                }
                return FileVisitResult.CONTINUE;
            }
        });
        List<String> broken = new ArrayList<>();
        pages.stream().sorted().forEach(p -> broken.addAll(brokenLinks(root, p)));
        assertEquals(List.of(), broken, "links in Markdown pages that lead nowhere (page:line: link)");
    }

    @Test
    void aLinkToAMissingFileIsFoundAndOneToAnExistingFileIsNot() throws IOException {
        Path root = Files.createTempDirectory("links");
        Files.createDirectories(root.resolve("docs"));
        Files.writeString(root.resolve("docs/a.md"),
                "see [b](b.md#top), [gone](../gone/README.md) and [web](https://x.org)\n");
        Files.writeString(root.resolve("docs/b.md"), "# top\n");
        assertEquals(List.of("docs/a.md:1: ../gone/README.md"), brokenLinks(root, root.resolve("docs/a.md")));
    }

    static List<String> brokenLinks(Path root, Path page) {
        List<String> broken = new ArrayList<>();
        List<String> lines = read(page);
        for (int i = 0; i < lines.size(); i++) {
            Matcher m = LINK.matcher(lines.get(i));
            while (m.find()) {
                String target = m.group(1);
                if (target.matches("^[a-zA-Z][a-zA-Z0-9+.-]*:.*") || target.startsWith("/")) {
                    continue; // the web, mail, or an absolute path (not a repository link)
                }
                if (!Files.exists(page.getParent().resolve(target).normalize())) {
                    broken.add(root.relativize(page) + ":" + (i + 1) + ": " + target);
                }
            }
        }
        return broken;
    }

    /** Build output, Git's folder, and templates in resources (their links are relative to where they are written). */
    private static boolean skipped(Path dir) {
        String name = dir.getFileName().toString();
        return name.equals("target") || name.equals("build") || name.equals("node_modules") || name.startsWith(".")
                || dir.endsWith(Path.of("src", "main", "resources"));
    }

    private static List<String> read(Path page) {
        try {
            return Files.readAllLines(page);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
