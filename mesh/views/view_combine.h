// Combining views: their elements into one view, or their data as the time steps of one.
#pragma once

#include "mesh/views/view.h"

namespace geomesh::post {

// Which views are combined: all of them, or those sharing a name (one result per name).
enum class CombineGroups { All, ByName };

// Combine Elements (Views) / ElementsByViewName: each group becomes its first view, holding
// the elements of all (lists of the same shape, kind and order joined; time steps must
// agree, else the group is left as it is). Returns how many views were merged away.
int combineElements(ViewStore& views, CombineGroups groups);
// Combine TimeSteps / TimeStepsByViewName: each group becomes its first view, whose time
// steps are those of every view in turn (the views must hold the same elements in the same
// order, else the group is left as it is). Returns how many views were merged away.
int combineTimeSteps(ViewStore& views, CombineGroups groups);

}  // namespace geomesh::post
