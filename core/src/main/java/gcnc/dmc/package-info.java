/**
 * The DMC program as data: typed Galil commands with their source ({@link gcnc.dmc.Instruction}),
 * printed, read back, packed into lines, split into the program and stream forms.
 */
package gcnc.dmc;
