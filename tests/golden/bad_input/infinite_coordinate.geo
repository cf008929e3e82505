Point(1) = {0, Log(0), 0};
