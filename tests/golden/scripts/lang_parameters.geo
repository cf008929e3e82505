// DefineConstant with attribute lists, overridden from the command line with -setnumber and
// -setstring, and the parameters read back.
DefineConstant[
  nx = {10, Min 1, Max 100, Step 1, Name "Parameters/Mesh/nx"},
  ny = {4, Name "Parameters/Mesh/ny", Help "cells across"},
  ratio = {1.5, Choices {1.5, 2}, Name "Parameters/ratio"},
  label = {"plate", Name "Parameters/label"},
  plain = 7
];
DefineConstant[ nx = 99 ];
Printf("nx %g ny %g ratio %g plain %g", nx, ny, ratio, plain);
Printf(StrCat("label ", label));
Printf("by name %g %g", GetNumber("Parameters/Mesh/nx"), GetNumber("Parameters/Mesh/ny"));
Printf(GetString("Parameters/label"));
h = DefineNumber[0.25, Name "Parameters/h"];
Printf("h %g", h);
s = DefineString["abc", Name "Parameters/s"];
Printf(s);
