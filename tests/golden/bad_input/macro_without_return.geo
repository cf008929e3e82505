Macro M
  a = 1;
