/**
 * Stage 2, flow: hands the checker the blocks in the order the control runs them (M98/M97 calls, M99
 * returns, macro B statements; docs/program-flow.md); a program without them streams through unchanged.
 */
package gcnc.flow;
