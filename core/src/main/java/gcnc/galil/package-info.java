/**
 * Stage 5, the DMC code generators ({@link gcnc.galil.Dialect}: galil and thesis): steps in,
 * typed {@link gcnc.dmc.Instruction}s out, each number held against the controller's limits.
 */
package gcnc.galil;
