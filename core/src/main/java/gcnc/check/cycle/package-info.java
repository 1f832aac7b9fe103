/**
 * Canned cycles (drilling and pecking, roughing, threading) expanded into ordinary
 * checked blocks at the cycle's line (docs/cycles.md).
 */
package gcnc.check.cycle;
