/**
 * The syntax actions of thesis §4.2.2, one class per action (SaNN), applied to a block's words
 * as the checker reads them (tables/syntax_actions.csv lists them).
 */
package gcnc.check.action;
