// Include of a sibling file that defines a macro and values; the includer then uses them.
Include "lang_include_part.geo";
Printf("from the part: width %g, %g points", part_width, newp - 1);
Call PartReport;
width = 2;
Include "lang_include_part.geo";
Printf("again: width %g, %g points", part_width, newp - 1);
