/**
 * Stage 4, plan: checked blocks into {@link gcnc.plan.Step}s, the motions joined into vector
 * sequences with their corner speeds ({@link gcnc.plan.Contouring}) or each stopped ({@link gcnc.plan.ExactStop}).
 */
package gcnc.plan;
