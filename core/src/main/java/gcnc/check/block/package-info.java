/**
 * The end-of-block operations of thesis §4.2.2, one class per operation (EbNN), run after a
 * block's words are read (tables/block_checks.csv lists them).
 */
package gcnc.check.block;
