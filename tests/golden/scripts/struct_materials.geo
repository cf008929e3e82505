// Material data kept in Structs, as GetDP-style models do: a namespace per kind of data,
// enumerations for region types, appended members, and a loop over a namespace.
Struct Mat::Iron [ Tag 100, mur 1000, sigma 1e7, label "iron", curve {0, 0.5, 1.2, 1.6} ];
Struct Mat::Copper [ mur 1, sigma 5.96e7, label "copper" ];
Struct Mat::Air [ mur 1, label "air" ];
Struct Region [ Enum, NONE, CONDUCTOR, MAGNETIC, BOUNDARY ];
Struct Region (Append) [ Enum, INFINITY ];

Printf("materials: %g", DimNameSpace(Mat));
// NameStruct finds a Struct by its tag; Iron set 100, the others follow it.
For t In {100:99 + DimNameSpace(Mat)}
  name = NameStruct[Mat::#t];
  Printf(Sprintf(StrCat("%g ", name, ": tag %g, mur %g, sigma %g"), t, Mat::S2N[name].Tag,
         Mat::S2N[name].mur, GetForced(Mat::S2N[name].sigma, 0)));
EndFor
Printf("iron curve: %g points, last %g", #Mat::Iron.curve(), Mat::Iron.curve(3));
Printf(StrCat("label of copper: ", Mat::Copper.label));
Printf("regions: %g %g %g %g", Region.NONE, Region.MAGNETIC, Region.INFINITY, Region);
If (Exists(Mat::Air.sigma))
  Printf("air conducts");
Else
  Printf("air does not conduct");
  Struct Mat::Air (Append) [ sigma 0 ];
EndIf
Printf("air sigma now %g", Mat::Air.sigma);
type = Region.CONDUCTOR;
If (type == Region.CONDUCTOR)
  Printf("conductor region %g", type);
EndIf
