// Struct semantics: tags, members, namespaces, Append, Enum, GetForced, Exists, and errors.
#include <gtest/gtest.h>

#include "script_runner.h"

namespace geomesh::testing {
namespace {

TEST(Structs, MembersOfEveryKind) {
  EXPECT_EQ(printed(R"(
Struct Mat [ Tag 3, epsr 5, mu {1, 2, 3}, label "iron", names Str[{"a", "bb"}] ];
Printf("%g %g %g %g %g", Mat, Mat.Tag, Mat.epsr, Mat.mu(1), #Mat.mu());
Printf(StrCat(Mat.label, "/", Mat.names(1)));
x() = Mat.mu();
Printf("%g %g %g %g", #x(), Mat.mu, Mat.mu[2], #Mat.names());
)"),
            "3 3 5 2 3\niron/bb\n3 1 3 2\n");
}

TEST(Structs, TagsCountFromTheLargestOfTheirNamespace) {
  EXPECT_EQ(printed(R"(
Struct A [ Tag 10 ]; Struct B [ Tag 2 ]; Struct C [ ];
Struct NS::D [ v 1 ]; Struct NS::E [ v 2 ];
t = Struct F [ v 3 ];
Printf("%g %g %g %g %g %g", A, B, C, NS::D, NS::E, t);
Printf("%g %g %g", DimNameSpace(), DimNameSpace(NS), DimNameSpace(None));
)"),
            "10 2 11 1 2 12\n4 2 0\n");
}

TEST(Structs, AppendAddsButNeverOverwrites) {
  EXPECT_EQ(printed(R"(
Struct D [ v 1 ];
Struct D (Append) [ v 2, w 3 ];
Printf("%g %g %g", D.v, D.w, D);
)"),
            "1 3 1\n");
}

TEST(Structs, EnumerationsAndFlags) {
  EXPECT_EQ(printed(R"(
Struct T::R [ Enum, NONE, PHYS, SKIN ];
Struct T::R2 [ Enum, PHYS 10, SKIN, GATE 20, BC ];
Struct T::R (Append) [ Enum, CUTBOX ];
Struct F [ Enum, Tag 5, x, y ];
Struct G [ x, y 4, z ];
Printf("%g %g %g %g %g %g", T::R.NONE, T::R.SKIN, T::R.CUTBOX, T::R2.SKIN, T::R2.BC, F.y);
Printf("%g %g %g", G.x, G.y, G.z);
)"),
            "0 2 3 11 21 7\n1 4 1\n");
}

TEST(Structs, NamesInLoopsStringsAndIndices) {
  EXPECT_EQ(printed(R"(
For i In {1:3}
  Struct NS::S~{i} [ v 10 * i ];
EndFor
For i In {1:DimNameSpace(NS)}
  id = NameStruct[NS::#i];
  Printf(Sprintf[StrCat["%g: ", id, " %g"], i, NS::S2N[id].v]);
EndFor
Struct G [ v 1 ];
Printf("%g %s", S2N["G"], NameStruct(#1));
)"),
            "1: S_1 10\n2: S_2 20\n3: S_3 30\n1 G\n");
}

// Exists answers the name of a Struct with its tag (5 for L below), as Gmsh does.
TEST(Structs, GetForcedAndExists) {
  EXPECT_EQ(printed(R"(
x = 12; l() = {11, 22};
Struct N::S [ Dim 2 ];
Struct K [ Tag 4 ];
Struct L [ m {1, 2, 3} ];
Printf("%g %g %g %g", GetForced(x, 1), GetForced(y, 1), GetForced(y), GetForced(l(9), 5));
Printf("%g %g %g", GetForced(N::S.Nope, -1), GetForced(L.m(99), -1), GetForced(L.m(1), -1));
Printf("%g %g %g %g %g", Exists(x), Exists(y), Exists(N::S.Dim), Exists(N::S.Nope), Exists(L));
)"),
            "12 1 0 5\n-1 -1 2\n1 0 1 0 5\n");
}

TEST(Structs, AVariableHidesAStructOfTheSameName) {
  EXPECT_EQ(printed("Struct M [ Tag 3 ];\nM = 2;\nPrintf(\"%g\", M);\n"), "2\n");
}

TEST(Structs, UnknownStructsAndMembersAreLocatedErrors) {
  EXPECT_EQ(firstLineOf("Struct Material [ epsr 5 ];\nx = Materal.epsr;\n"),
            "test.geo:2:5: error: unknown Struct 'Materal'; did you mean 'Material'?");
  EXPECT_EQ(firstLineOf("Struct Material [ epsr 5 ];\nx = Material.eps;\n"),
            "test.geo:2:5: error: unknown member 'eps' of Struct 'Material'; did you mean 'epsr'?");
  EXPECT_EQ(firstLineOf("Struct NS::M [ v 5 ];\nx = NX::M.v;\n"),
            "test.geo:2:5: error: unknown Struct namespace 'NX'; did you mean 'NS'?");
  EXPECT_EQ(firstLineOf("Struct M [ l {1, 2} ];\nx = M.l(2);\n"),
            "test.geo:2:9: error: index 2 out of range for member 'l' of Struct 'M' (2 items)");
}

TEST(Structs, RedefinitionAndMemberAssignmentAreRefused) {
  EXPECT_EQ(firstLineOf("Struct M [ v 1 ];\nStruct M [ v 2 ];\n"),
            "test.geo:2:1: error: Struct 'M' is already defined; add members with "
            "'Struct M (Append) [...]'");
  EXPECT_EQ(firstLineOf("Struct M [ v 1 ];\nM.v = 2;\n"),
            "test.geo:2:1: error: members of a Struct cannot be assigned: give 'v' its value in "
            "the Struct definition");
}

}  // namespace
}  // namespace geomesh::testing
