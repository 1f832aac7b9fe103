/**
 * Shared by all stages: the thesis's tables and gcnc's own, loaded from tables/ (or a folder given
 * by the user), and the explanations of {@code gcnc explain}.
 */
package gcnc.tables;
