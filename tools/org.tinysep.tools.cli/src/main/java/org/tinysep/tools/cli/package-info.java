/**
 * The command lines of the tools around the platform (the simulator, the evaluation, the benchmarks), parsed by
 * picocli one way: {@link Cli} parses, refuses an unknown flag or a bad value with one line naming it, prints the
 * usage on {@code --help} and maps a run's outcome to an exit code; {@link OptionTypes} are the value types they
 * share. Not for production code: never deployed.
 */
@Export
@Version("1.0.0")
package org.tinysep.tools.cli;

import org.osgi.annotation.bundle.Export;
import org.osgi.annotation.versioning.Version;
