/** Measurements of the machine the platform runs on, shared by the integration tests and the benchmarks. */
package org.tinysep.simulator.measure;
