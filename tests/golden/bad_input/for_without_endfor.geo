For i In {1:3}
  Printf("%g", i);
