Point(1) = {Sqrt(-1), 0, 0};
