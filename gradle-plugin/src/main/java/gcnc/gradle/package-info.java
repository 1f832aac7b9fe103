/**
 * The Gradle plugin ({@code id 'gcnc.lathe'}, docs/gradle-plugin.md): check and compile tasks over
 * {@link gcnc.Session}, with GCC-style, JSON and SARIF reports and setup sheets.
 */
package gcnc.gradle;
