/**
 * Shared by all stages: the diagnostic codes, a finding with its place, the sink that folds and
 * caps them, the renderers (GNU, JSON, SARIF) and the waivers.
 */
package gcnc.diag;
