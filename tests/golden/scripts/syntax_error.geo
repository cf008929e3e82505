// A syntax error: the missing ";" is reported right after the token it should follow.
Point(1) = {0, 0, 0, 0.1}
Point(2) = {1, 0, 0, 0.1};
