package org.tinysep.amica.window.tutorial;

import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Matcher;
import java.util.regex.Pattern;

/**
 * Checks a Java source that cannot be compiled here (a Pax Exam test): every {@code java.*} and
 * {@code org.tinysep.*} import must name a class that exists (loadable, or a source file in the repository), every
 * static import a member of it, and the class it extends must exist in its own package.
 */
final class Imports {

    private static final Pattern IMPORT = Pattern.compile("(?m)^import (static )?([\\w.]+);");
    private static final Pattern PACKAGE = Pattern.compile("(?m)^package ([\\w.]+);");
    private static final Pattern EXTENDS = Pattern.compile("\\bclass \\w+ extends (\\w+)");

    private Imports() {
    }

    static List<String> check(String source, ClassLoader loader, Path repo, Path scratch) {
        List<String> problems = new ArrayList<>();
        Matcher m = IMPORT.matcher(source);
        while (m.find()) {
            boolean isStatic = m.group(1) != null;
            String name = m.group(2);
            if (!name.startsWith("java.") && !name.startsWith("org.tinysep.")) {
                continue; // Pax Exam and JUnit 4 are not on this class path
            }
            String type = isStatic ? name.substring(0, name.lastIndexOf('.')) : name;
            Class<?> c = load(type, loader);
            if (c == null && !sourceExists(type, repo, scratch)) {
                problems.add("no class " + type);
            } else if (isStatic && c != null && !hasMember(c, name.substring(name.lastIndexOf('.') + 1))) {
                problems.add("no member " + name);
            }
        }
        Matcher pkg = PACKAGE.matcher(source);
        Matcher ext = EXTENDS.matcher(source);
        if (pkg.find() && ext.find() && !sourceExists(pkg.group(1) + "." + ext.group(1), repo, scratch)) {
            problems.add("no class " + ext.group(1) + " in package " + pkg.group(1));
        }
        return problems;
    }

    private static Class<?> load(String name, ClassLoader loader) {
        try {
            return Class.forName(name, false, loader);
        } catch (ClassNotFoundException | LinkageError e) {
            return null;
        }
    }

    private static boolean hasMember(Class<?> c, String member) {
        return Arrays.stream(c.getFields()).map(Field::getName).anyMatch(member::equals)
                || Arrays.stream(c.getMethods()).map(Method::getName).anyMatch(member::equals);
    }

    /** @return whether some module of the repository (or the scratch copy) has a source file for the class */
    private static boolean sourceExists(String type, Path repo, Path scratch) {
        String file = type.replace('.', '/') + ".java";
        for (Path base : List.of(repo, scratch)) {
            for (String module : List.of("itests", "api")) {
                for (String set : List.of("src/main/java/", "src/test/java/")) {
                    if (Files.isRegularFile(base.resolve(module).resolve(set + file))) {
                        return true;
                    }
                }
            }
        }
        return false;
    }
}
