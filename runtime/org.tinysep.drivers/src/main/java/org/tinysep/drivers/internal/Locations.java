package org.tinysep.drivers.internal;

import java.net.URI;
import java.nio.file.Path;
import java.util.Optional;
import java.util.regex.Pattern;

/**
 * Maps a drivers-list {@code FILE_PATH} to a bundle location and back: a path is relative to {@code tinysep.home}
 * (or absolute), a URL is used as it is — only {@code file:} and {@code https:} URLs are installed
 * ({@link #refusal}): a plain {@code http:} download can be changed on its way, other schemes are not checked.
 */
final class Locations {

    private static final Pattern URL = Pattern.compile("[a-zA-Z][a-zA-Z0-9+.-]+:.*");

    private final Path home;

    /** @param home {@code tinysep.home}, or null (paths are then relative to the working directory) */
    Locations(Path home) {
        this.home = (home == null ? Path.of("") : home).toAbsolutePath().normalize();
    }

    /** @return why {@code filePath} is not installed (a URL that is neither file: nor https:), or empty */
    Optional<String> refusal(String filePath) {
        if (!URL.matcher(filePath).matches()) {
            return Optional.empty();
        }
        String scheme = filePath.substring(0, filePath.indexOf(':')).toLowerCase(java.util.Locale.ROOT);
        return scheme.equals("file") || scheme.equals("https") ? Optional.empty()
                : Optional.of(scheme + ": URLs are not installed, only file: and https: (docs/runtime-changes.md)");
    }

    /** @return the bundle location (URL) for {@code filePath} */
    String url(String filePath) {
        return URL.matcher(filePath).matches() ? filePath : file(filePath).orElseThrow().toUri().toString();
    }

    /** @return the local file behind {@code filePath}, when it names one (a path or a {@code file:} URL) */
    Optional<Path> file(String filePath) {
        if (!URL.matcher(filePath).matches()) {
            return Optional.of(home.resolve(filePath).normalize());
        }
        if (filePath.startsWith("file:")) {
            try {
                return Optional.of(Path.of(URI.create(filePath)).normalize());
            } catch (RuntimeException e) {
                return Optional.empty();
            }
        }
        return Optional.empty();
    }

    /** @return the {@code FILE_PATH} for an installed bundle's location: relative when the file lies under home */
    String filePath(String bundleLocation) {
        Optional<Path> f = bundleLocation.startsWith("file:") ? file(bundleLocation) : Optional.empty();
        if (f.isPresent() && f.get().startsWith(home)) {
            return home.relativize(f.get()).toString().replace('\\', '/');
        }
        return bundleLocation;
    }

    /** @return whether the bundle location is a local file under {@code folder} */
    boolean isUnder(String bundleLocation, Path folder) {
        Optional<Path> f = bundleLocation.startsWith("file:") ? file(bundleLocation) : Optional.empty();
        return folder != null && f.isPresent() && f.get().startsWith(folder.toAbsolutePath().normalize());
    }
}
