For i In {1:10:0}
EndFor
