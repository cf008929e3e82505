a = 1;
Else
