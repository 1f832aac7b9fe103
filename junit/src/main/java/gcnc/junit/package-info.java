/**
 * JUnit 5 fixtures for a shop's own tests: assertions over a program's findings and where its path goes,
 * through {@link gcnc.Session}.
 */
package gcnc.junit;
