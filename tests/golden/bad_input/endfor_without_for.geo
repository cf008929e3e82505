a = 1;
EndFor
