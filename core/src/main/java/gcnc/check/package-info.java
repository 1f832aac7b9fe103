/**
 * Stage 3, check: each raw block against the tables, the machine and the control's modal state,
 * into checked blocks in machine counts ({@link gcnc.check.Checker}); nose compensation and corners.
 */
package gcnc.check;
