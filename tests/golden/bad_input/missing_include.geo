a = 1;
Include "does_not_exist.geo";
