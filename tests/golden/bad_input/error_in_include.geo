a = 1;
Include "error_in_include.inc";
