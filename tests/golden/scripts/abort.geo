// Abort stops reading the script; what was defined before it is still meshed.
Printf("before");
Point(1) = {0, 0, 0, 0.1};
Abort;
Printf("after");
Point(2) = {1, 0, 0, 0.1};
