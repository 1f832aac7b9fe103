/*
 * The part-program language of the thesis (§3.3, Tables 11/12), widened to read real Haas and
 * Fanuc lathe programs. See docs/grammar.md for the language, the error numbers and the
 * deviations from the thesis.
 *
 * The lexer rules replace the thesis's transition matrix. They cover EVERY character, so the
 * lexer itself never fails: malformed input becomes an error token (NOT_INTEGER, BAD_NUMBER,
 * BARE_LETTER, TEXT, MACRO, STRAY, ILLEGAL, NESTED_COMMENT, UNCLOSED_COMMENT) that
 * gcnc.parse.BlockReader turns into a numbered diagnostic. Ties between rules of equal match
 * length go to the rule written first, so the valid word rules come before the error rules.
 *
 * Every letter A-Z is a word letter: which letters a control reads is the checker's business
 * (error 4), not the grammar's.
 *
 * The parser rules document the block structure. BlockReader follows them in a small loop over
 * the lexer's tokens, one physical line at a time (streaming); BlockReaderAgreementTest checks
 * that the two agree.
 */
grammar GCode;

// ---- parser: one physical line is one block -------------------------------------------------

/** A program: lines separated by line ends. Blank and comment-only lines are empty. */
program   : line? (separator line?)* EOF ;

/** A comment that spans lines ends the block it opened in; words after it belong to its last line. */
separator : NEWLINE | SPANNING_COMMENT ;

/** A line with words is a block; a line holding only a block delete '/' makes no block. */
line      : block | BLOCK_DELETE ;

/**
 * The words of one line, in any order, with or without spaces between them (G01X10Z5), marked
 * for block delete by a '/' before the first word or right after a first N word (/N10, N10/), or
 * from the middle on by a '/' after other words (G00 X1. /M08). One '/' per line.
 */
block     : BLOCK_DELETE word+
          | SEQUENCE_WORD BLOCK_DELETE word*
          | word+ (BLOCK_DELETE word*)?
          ;

word      : SEQUENCE_WORD  // N: unsigned digits
          | INT_WORD       // G M O S T: unsigned digits (G1 = G01; the checker normalises)
          | TAPE_PROGRAM   // ':' and digits: Fanuc's ISO tape program number, the word O
          | FEED_WORD      // F: unsigned decimal
          | COORD_WORD     // every other letter: signed decimal
          | COMMA_WORD     // ',C' ',R' ',A': Haas chamfer, corner rounding, angle
          ;

// ---- lexer: words ----------------------------------------------------------------------------

// Haas and Fanuc controls ignore spaces, also inside a word: 'G 01', 'F 0.25', 'X- 2.5' and
// 'T1 01' are G01, F0.25, X-2.5 and T101. A word's text may hold spaces and tabs (SP) after its
// letter and sign and between the characters of its number; BlockReader takes them out.
SEQUENCE_WORD : [Nn] SP* DIGITS ;
INT_WORD      : [GgMmOoSsTt] SP* DIGITS ;
TAPE_PROGRAM  : ':' DIGITS ;
FEED_WORD     : [Ff] SP* UNSIGNED ;
COORD_WORD    : [A-EH-LP-RU-Za-eh-lp-ru-z] SP* ([+-] SP*)? UNSIGNED ;
/** Haas ',C' ',R' (G01 chamfer and corner rounding) and ',A' (an angle): a comma before the letter. */
COMMA_WORD    : ',' SP* [ACRacr] SP* ([+-] SP*)? UNSIGNED ;

/** Block delete, with its optional skip level 1-9 (a bare '/' is level 1). */
BLOCK_DELETE  : '/' [1-9]? ;

// ---- lexer: comments and layout --------------------------------------------------------------

/** ( ... ) on one line: whitespace. */
COMMENT          : '(' ~[()\r\n]* ')' -> skip ;
/** ( ... ) over several lines (same text as COMMENT; only wins when it holds a line end). */
SPANNING_COMMENT : '(' ~[()]* ')' ;
/** ';' and '%' (tape mark): the rest of the line is ignored. */
LINE_COMMENT     : [;%] ~[\r\n]* -> skip ;
/** Tabs are whitespace (the thesis made them illegal). */
WS               : [ \t]+ -> skip ;
NEWLINE          : '\r\n' | '\r' | '\n' ;

// ---- lexer: errors (never in a parser rule; each is one numbered diagnostic) -----------------

/** A letter with no number: G -> error 1, M -> error 2, any other -> error 6. */
BARE_LETTER      : [A-Za-z] ;
/** A letter followed by letters: a note outside a comment ("roughing pass", "Xabc"): error 109. */
TEXT             : [A-Za-z] [A-Za-z]+ ;
/** An integer word with a sign or decimal point (N1.5, S-100, :12.5): error 13. */
NOT_INTEGER      : [GgMmNnOoSsTt] SP* [+\-.0-9] NUMBERISH* | ':' DIGIT NUMBERISH* ;
/** A decimal word whose number is malformed (X+, X., X1.2.3, X--1, F-1, X10 -5): error 14. */
BAD_NUMBER       : [A-FH-LP-RU-Za-fh-lp-ru-z] SP* [+\-.0-9] NUMBERISH* ;
/** Fanuc macro B: a '#' variable or a '[ ]' expression: error 111 (the line's first error). */
MACRO            : [#[\]] ;
/** '(' inside a comment: error 54 (the thesis printed 150). The token ends at the inner '('. */
NESTED_COMMENT   : '(' ~[()]* '(' ;
/** A comment with no ')' before the end of the input: error 5. */
UNCLOSED_COMMENT : '(' ~[()]* ;
/** A number, sign, point or punctuation where a word should start: error 10 (so is a misplaced '/'). */
STRAY            : [0-9.+\-:,*=)] ;
/** Any other character ($, ", control characters, non-ASCII ...): error 3. */
ILLEGAL          : . ;

fragment DIGIT    : [0-9] ;
fragment SP       : [ \t] ;
/** Digits, with spaces between them (not before the first nor after the last). */
fragment DIGITS   : DIGIT (SP* DIGIT)* ;
fragment UNSIGNED : DIGITS (SP* '.' (SP* DIGITS)?)? | '.' SP* DIGITS ;
/** The characters of a malformed number, spaces among them (a trailing space is harmless there). */
fragment NUMBERISH : [+\-.0-9] | SP+ [+\-.0-9] ;
