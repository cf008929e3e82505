Point(1) = {0, 0, 0};
Physical Point(1.5) = {1};
