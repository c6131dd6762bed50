// Block syntax of the Siemens DIN language (Sinumerik 840D: `siemens-din`, and the DIN text of a
// `siemens-iso-m` program after G290).
//
// One parse is one block (a line; the reader has cut the `;` comment off). The grammar describes
// syntax only; the frontend (din_block_parser.cpp) checks the rest and decides what a name is:
// `X100` and `X=R1+5` are address words, `COUNT=5` assigns a variable, `MYKONTUR` calls a
// subprogram. Sources: siemens-840di-cycles notes §2 (the syntax its examples use) and the
// Sinumerik Programming Manual Fundamentals where those are silent (docs/din.md).
//
// Input conventions as for Iso.g4: letters upper-cased (names are case-insensitive), bytes >= 0x80
// replaced by 0x01 (they are only valid in strings, whose text the frontend takes from the
// original line). Words are separated by blanks (`G1 X10 Y20`), as Siemens programs write them.
grammar Din;

block
    : blockStart? item* EOF
    ;

// The control structures (IF ... ENDIF, WHILE, FOR, REPEAT, LOOP, CASE) stand alone in their
// block, with its number and labels: the frontend checks that. A PROC block is the first of its
// program: `PROC NAME(REAL A, VAR INT B) DISPLOF`, the attributes after the parameters. The name
// may be a number in a program called from ISO mode (`PROC 0010`, the body of G65 P10).

// Block skip '/', '/0' .. '/9'.
blockStart
    : SLASH NUMBER?
    ;

item
    : COLON NUMBER                                       # mainBlockItem
    | IDENT COLON                                        # labelItem
    | DEF typeName definition (COMMA definition)*        # defItem
    | IF expr jump jumpTarget                            # ifGotoItem
    | IF expr                                            # ifItem
    | ELSE                                               # elseItem
    | ENDIF                                              # endIfItem
    | WHILE expr                                         # whileItem
    | ENDWHILE                                           # endWhileItem
    | FOR name EQUALS expr TO expr                       # forItem
    | ENDFOR                                             # endForItem
    | REPEAT start=IDENT end=IDENT? (count=IDENT EQUALS expr)?  # repeatSectionItem
    | REPEAT                                             # repeatItem
    | UNTIL expr                                         # untilItem
    | LOOP                                               # loopItem
    | ENDLOOP                                            # endLoopItem
    | CASE expr OF caseBranch+ (DEFAULT jump jumpTarget)?  # caseItem
    | PROC procName=(IDENT | NUMBER) (LPAREN (parameter (COMMA parameter)*)? RPAREN)? attributes+=IDENT*  # procItem
    | RET                                                # retItem
    | jump jumpTarget                                    # gotoItem
    | name EQUALS expr                                   # assignItem
    | IDENT sign=(PLUS | MINUS) NUMBER                   # signedWordItem
    | WORD                                               # wordItem
    | WORDS                                              # wordsItem
    | IDENT LPAREN arguments RPAREN                      # callItem
    | IDENT                                              # nameItem
    ;

typeName
    : IDENT (LBRACK NUMBER RBRACK)?                      // INT REAL BOOL CHAR STRING[n] AXIS FRAME
    ;

// A variable and its initial value; arrays give their sizes: DEF REAL A[3,4].
definition
    : IDENT (LBRACK expr (COMMA expr)* RBRACK)? (EQUALS expr)?
    ;

// A parameter of a PROC: by value, or by reference (VAR); arrays give their sizes, the first may
// be left open (`VAR REAL A[,3]`).
parameter
    : VAR? typeName IDENT (LBRACK expr? (COMMA expr?)* RBRACK)?
    ;

// `7 GOTOF LABEL_1`: a constant of CASE and where it jumps.
caseBranch
    : (sign=(PLUS | MINUS)? NUMBER | STRING) jump jumpTarget
    ;

jump
    : GOTOF | GOTOB | GOTO | GOTOC
    ;

// A label, a block number (N100 or 100), or :n.
jumpTarget
    : IDENT
    | WORD
    | NUMBER
    | COLON NUMBER
    ;

// What an assignment writes: an address or variable (`X`, `X1`, `COUNT`, `R10`), an array
// element or R[expr].
name
    : (IDENT | WORD) (LBRACK expr (COMMA expr)* RBRACK)?
    ;

// `F()` is one empty argument, as `F(,)` is two: the builder reads the first as none.
arguments
    : argument (COMMA argument)*
    ;

argument
    : expr?
    ;

// Siemens precedence, loosest first: comparison, string concatenation, OR, XOR, AND, B_OR,
// B_XOR, B_AND, + -, * / DIV MOD, unary NOT B_NOT and signs.
expr
    : concat (compareOp concat)*
    ;

compareOp
    : EQEQ | NOTEQ | LESS | GREATER | LESSEQ | GREATEREQ
    ;

concat
    : orExpr (CONCAT orExpr)*
    ;

orExpr
    : xorExpr (OR xorExpr)*
    ;

xorExpr
    : andExpr (XOR andExpr)*
    ;

andExpr
    : bOrExpr (AND bOrExpr)*
    ;

bOrExpr
    : bXorExpr (B_OR bXorExpr)*
    ;

bXorExpr
    : bAndExpr (B_XOR bAndExpr)*
    ;

bAndExpr
    : additive (B_AND additive)*
    ;

additive
    : multiplicative (addOp multiplicative)*
    ;

addOp
    : PLUS | MINUS
    ;

multiplicative
    : unary (mulOp unary)*
    ;

mulOp
    : STAR | SLASH | DIV | MOD
    ;

unary
    : op=(PLUS | MINUS | NOT | B_NOT) unary
    | primary
    ;

primary
    : NUMBER
    | STRING
    | IDENT LPAREN arguments RPAREN
    | name
    | LPAREN expr RPAREN
    ;

// ---- Lexer -------------------------------------------------------------------------------

STRING      : '"' ~["]* '"' ;
OPEN_STRING : '"' ~["]* ;           // no closing '"' before the end of the block: reported

NUMBER : [0-9]+ ('.' [0-9]*)? | '.' [0-9]+ ;

DEF      : 'DEF' ;
IF       : 'IF' ;
ELSE     : 'ELSE' ;
ENDIF    : 'ENDIF' ;
WHILE    : 'WHILE' ;
ENDWHILE : 'ENDWHILE' ;
FOR      : 'FOR' ;
ENDFOR   : 'ENDFOR' ;
REPEAT   : 'REPEAT' | 'REPEATB' ;
UNTIL    : 'UNTIL' ;
LOOP     : 'LOOP' ;
ENDLOOP  : 'ENDLOOP' ;
CASE     : 'CASE' ;
OF       : 'OF' ;
DEFAULT  : 'DEFAULT' ;
TO       : 'TO' ;
PROC     : 'PROC' ;
VAR      : 'VAR' ;
RET      : 'RET' ;
GOTOF    : 'GOTOF' ;
GOTOB    : 'GOTOB' ;
GOTO     : 'GOTO' ;
GOTOC    : 'GOTOC' ;

OR    : 'OR' ;
XOR   : 'XOR' ;
AND   : 'AND' ;
NOT   : 'NOT' ;
DIV   : 'DIV' ;
MOD   : 'MOD' ;
B_OR  : 'B_OR' ;
B_XOR : 'B_XOR' ;
B_AND : 'B_AND' ;
B_NOT : 'B_NOT' ;

// An address letter and its number: `X100`, `G1`, `N10`, `R1`, `X-` is IDENT and a sign.
// Several written without blanks (`G1X10.Y5`) are WORDS; a name (`MA1`, `POSITION1`) is IDENT.
WORD  : [A-Z] NUMBER_TEXT ;
WORDS : ([A-Z] NUMBER_TEXT)+ ;
IDENT : [A-Z_$] [A-Z0-9_]* ;
fragment NUMBER_TEXT : [0-9]+ ('.' [0-9]*)? | '.' [0-9]+ ;

EQEQ      : '==' ;
NOTEQ     : '<>' ;
LESSEQ    : '<=' ;
GREATEREQ : '>=' ;
CONCAT    : '<<' ;
LESS      : '<' ;
GREATER   : '>' ;
EQUALS    : '=' ;
PLUS      : '+' ;
MINUS     : '-' ;
STAR      : '*' ;
SLASH     : '/' ;
LPAREN    : '(' ;
RPAREN    : ')' ;
LBRACK    : '[' ;
RBRACK    : ']' ;
COMMA     : ',' ;
COLON     : ':' ;

WS : [ \t]+ -> skip ;

// Anything else; the frontend reports it as an unexpected character.
ERROR_CHAR : . ;
