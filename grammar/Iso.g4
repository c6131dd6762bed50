// Block syntax of the ISO family: FANUC (Macro B), Mazak EIA/ISO, Sinumerik ISO mode.
//
// One parse is one block (a line, or the part of a line between ';' end-of-block marks: the
// reader splits lines before parsing). The grammar describes syntax only; the frontend checks
// the rest (skip level range, integer N/O numbers, function arity) while building the AST.
//
// Input conventions (the frontend prepares the text before lexing, keeping columns):
//  - letters are upper-cased (programs may be written in lower case);
//  - bytes >= 0x80 are replaced by 0x01: they are only valid inside comments, whose text the
//    frontend takes from the original line.
// Spaces and tabs may appear anywhere between tokens (`G 90`, `X- 20.`) and may be omitted
// (`G1X10.Y5.`, `IF[#1EQ#2]GOTO5`): a keyword is two or more letters, which never occurs in a
// word block because every address letter is followed by its value.
grammar Iso;

block
    : blockStart? item* EOF
    ;

// '%' tape mark, or block skip '/' with an optional level ('/', '/1' .. '/9').
blockStart
    : PERCENT
    | SLASH NUMBER?
    ;

item
    : COMMENT                         # commentItem
    | LETTER value                    # wordItem
    | COMMA LETTER value              # commaWordItem
    | COLON NUMBER                    # colonProgramItem
    | statement                       # statementItem
    ;

// The value of an address: a number, a variable, a bracketed expression, each with a sign.
value
    : sign=(PLUS | MINUS)? (NUMBER | variable | bracket)
    ;

variable
    : HASH (NUMBER | bracket)
    ;

bracket
    : LBRACK expr RBRACK
    ;

// Macro B statements.
statement
    : variable EQUALS expr                          # assignStatement
    | GOTO target                                   # gotoStatement
    | IF bracket GOTO target                        # ifGotoStatement
    | IF bracket THEN variable EQUALS expr          # ifThenStatement
    | WHILE bracket DO NUMBER                       # whileStatement
    | END NUMBER                                    # endStatement
    ;

target
    : sign=(PLUS | MINUS)? (NUMBER | variable | bracket)
    ;

// FANUC precedence, loosest first: comparison, additive (+ - OR XOR),
// multiplicative (* / AND MOD), unary sign, then functions, brackets and operands.
expr
    : additive (compareOp additive)*
    ;

compareOp
    : EQ | NE | GT | LT | GE | LE
    ;

additive
    : multiplicative (addOp multiplicative)*
    ;

addOp
    : PLUS | MINUS | OR | XOR
    ;

multiplicative
    : unary (mulOp unary)*
    ;

mulOp
    : STAR | SLASH | AND | MOD
    ;

unary
    : sign=(PLUS | MINUS) unary
    | primary
    ;

primary
    : NUMBER
    | variable
    | bracket
    | call
    ;

// ATAN[a]/[b] and ATAN[a,b] are the two-argument arc tangent.
call
    : ATAN LBRACK expr (COMMA expr)? RBRACK (SLASH LBRACK expr RBRACK)?
    | FUNC LBRACK expr (COMMA expr)* RBRACK
    ;

// ---- Lexer -------------------------------------------------------------------------------

COMMENT      : '(' ~[)]* ')' ;
OPEN_COMMENT : '(' ~[)]* ;          // no ')' before the end of the block: reported

NUMBER : [0-9]+ ('.' [0-9]*)? | '.' [0-9]+ ;

GOTO  : 'GOTO' ;
IF    : 'IF' ;
THEN  : 'THEN' ;
WHILE : 'WHILE' | 'WH' ;
DO    : 'DO' ;
END   : 'END' ;

OR  : 'OR' ;
XOR : 'XOR' ;
AND : 'AND' ;
MOD : 'MOD' ;
EQ  : 'EQ' ;
NE  : 'NE' ;
GT  : 'GT' ;
LT  : 'LT' ;
GE  : 'GE' ;
LE  : 'LE' ;

ATAN : 'ATAN' | 'ATN' ;
FUNC
    : 'SIN' | 'COS' | 'TAN' | 'ASIN' | 'ACOS' | 'SQRT' | 'SQR' | 'ABS' | 'BIN' | 'BCD'
    | 'ROUND' | 'RND' | 'FIX' | 'FUP' | 'LN' | 'EXP' | 'POW' | 'ADP'
    ;

LETTER : [A-Z] ;

HASH    : '#' ;
LBRACK  : '[' ;
RBRACK  : ']' ;
PLUS    : '+' ;
MINUS   : '-' ;
STAR    : '*' ;
SLASH   : '/' ;
EQUALS  : '=' ;
COMMA   : ',' ;
COLON   : ':' ;
PERCENT : '%' ;

WS : [ \t]+ -> skip ;

// Anything else; the frontend reports it as an unexpected character.
ERROR_CHAR : . ;
