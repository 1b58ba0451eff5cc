package org.tinysep.inactivity.internal;

/** Which limits Inactivity Recognition uses (configuration key {@code detector}). */
public enum Detector {
    /** Limits learned per room, time of day and sleep from the home's own history (cold start: THESIS's). */
    LEARNED,
    /** The thesis's fixed per-room limits ({@code typeLimits}, {@code roomLimits}, {@code defaultLimitMinutes}). */
    THESIS
}
