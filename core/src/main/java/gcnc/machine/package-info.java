/**
 * Machine profiles (tables/machines/*.machine) and the controls they name (tables/controls/): G and
 * M functions by role, power-up state and rules, the Galil model and its limits, tool wear.
 */
package gcnc.machine;
