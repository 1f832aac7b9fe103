/*
 * The part-program language of the thesis (§3.3, Tables 11/12), as gcnc accepts it.
 * See docs/grammar.md for the language, the error numbers and the deviations from the thesis.
 *
 * The lexer rules replace the thesis's transition matrix. They cover EVERY character, so the
 * lexer itself never fails: malformed input becomes an error token (NOT_INTEGER, BAD_NUMBER,
 * BARE_LETTER, UNDEFINED_LETTER, STRAY, ILLEGAL, NESTED_COMMENT, UNCLOSED_COMMENT) that
 * gcnc.parse.BlockReader turns into a numbered diagnostic. Ties between rules of equal match
 * length go to the rule written first, so the valid word rules come before the error rules.
 *
 * The parser rules document the block structure. BlockReader follows them in a small loop over
 * the lexer's tokens, one physical line at a time (streaming); BlockReaderGrammarTest checks that
 * the two agree.
 */
grammar GCode;

// ---- parser: one physical line is one block -------------------------------------------------

/** A program: blocks separated by line ends. Blank and comment-only lines are empty. */
program   : block? (separator block?)* EOF ;

/** A comment that spans lines ends the block it opened in; words after it belong to its last line. */
separator : NEWLINE | SPANNING_COMMENT ;

/** The words of one line, in any order, with or without spaces between them (G01X10Z5). */
block     : word+ ;

word      : INT_WORD     // G M N O P S T: unsigned digits (G1 = G01; the checker normalises)
          | FEED_WORD    // F: unsigned decimal
          | COORD_WORD   // I K R U W X Z: signed decimal
          ;

// ---- lexer: words ----------------------------------------------------------------------------

INT_WORD    : [GgMmNnOoPpSsTt] DIGIT+ ;
FEED_WORD   : [Ff] UNSIGNED ;
COORD_WORD  : [IiKkRrUuWwXxZz] [+-]? UNSIGNED ;

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

/** A word letter with no number: G -> error 1, M -> error 2, any other -> error 6. */
BARE_LETTER      : [GgMmNnOoPpSsTtFfIiKkRrUuWwXxZz] ;
/** An integer word with a sign or decimal point (N1.5, S-100): error 13. */
NOT_INTEGER      : [GgMmNnOoPpSsTt] [+\-.0-9]+ ;
/** A decimal word whose number is malformed (X+, X., X1.2.3, X--1, F-1): error 14. */
BAD_NUMBER       : [FfIiKkRrUuWwXxZz] [+\-.0-9]+ ;
/** A letter the language does not have: error 4. */
UNDEFINED_LETTER : [AaBbCcDdEeHhJjLlQqVvYy] ;
/** '(' inside a comment: error 54 (the thesis printed 150). The token ends at the inner '('. */
NESTED_COMMENT   : '(' ~[()]* '(' ;
/** A comment with no ')' before the end of the input: error 5. */
UNCLOSED_COMMENT : '(' ~[()]* ;
/** A number, sign, point or punctuation where a word should start: error 10. */
STRAY            : [0-9.+\-:,*/=#)[\]] ;
/** Any other character ($, ", control characters, non-ASCII ...): error 3. */
ILLEGAL          : . ;

fragment DIGIT    : [0-9] ;
fragment UNSIGNED : DIGIT+ ('.' DIGIT*)? | '.' DIGIT+ ;
