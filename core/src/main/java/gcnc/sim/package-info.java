/**
 * Stage 6, sim: replays the emitted DMC (never the G-code) on a model of the controller and the
 * machine, and judges the path, the stock, the tools and the time; draws the part.
 */
package gcnc.sim;
