// A syntax error: the missing ';' is reported at the next token's line and column.
Point(1) = {0, 0, 0, 0.1}
Point(2) = {1, 0, 0, 0.1};
