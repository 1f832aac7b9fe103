grammar GCode;
program : line* EOF ;
line : word* NEWLINE ;
word : LETTER NUMBER? ;
LETTER : [A-Za-z] ;
NUMBER : [+-]? [0-9]+ ;
NEWLINE : '\r'? '\n' ;
WS : [ ]+ -> skip ;
