/**
 * The checker's geometry and numbers: coordinates, arcs, corners, the tool nose, feeds and
 * spindle speeds, as functions with no modal state of their own.
 */
package gcnc.check.geom;
