Point(1) = {0, 0, 0};
Homology(1);
