package gcnc.check;

import gcnc.ir.CheckedBlock;

/**
 * What a block would do from a given state, checked but not committed: the block it would make
 * and the state it would leave ({@link Lookahead#peek}, {@link CycleHost#dry}).
 */
record Dry(CheckedBlock block, ModalState next) {
}
