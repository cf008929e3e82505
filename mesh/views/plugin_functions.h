// The plugins' entry points and the helpers they share (finding views, checking options).
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/views/plugins.h"
#include "mesh/views/view.h"

namespace geomesh::post::plugins {

// Each plugin: reads its options (the reference's names and defaults), adds or changes views.
void mathEval(const PluginOptions& options, PluginContext& context);
void modifyComponents(const PluginOptions& options, PluginContext& context);
void cutPlane(const PluginOptions& options, PluginContext& context);
void cutSphere(const PluginOptions& options, PluginContext& context);
void isosurface(const PluginOptions& options, PluginContext& context);
void cutGrid(const PluginOptions& options, PluginContext& context);
void integrate(const PluginOptions& options, PluginContext& context);
void analyseMeshQuality(const PluginOptions& options, PluginContext& context);
void skin(const PluginOptions& options, PluginContext& context);
void warp(const PluginOptions& options, PluginContext& context);
void newView(const PluginOptions& options, PluginContext& context);
void elementSize(const PluginOptions& options, PluginContext& context);
void curvature(const PluginOptions& options, PluginContext& context);
void vertexNormals(const PluginOptions& options, PluginContext& context);

// Throws PluginError "Plugin(name): message".
[[noreturn]] void fail(std::string_view plugin, const std::string& message);
// "Option = value" for error messages.
std::string optionText(std::string_view option, double value);

// The index of the view option `option` names (a negative value: the current, last view);
// throws PluginError naming the plugin, option and value when there is no such view.
std::size_t viewIndex(const PluginOptions& options, const PluginContext& context,
                      std::string_view plugin, const char* option = "View");
// The step option `option` as a step of `view`: -1 (or any negative value) when
// `allowAll`, else 0 .. stepCount - 1; throws PluginError otherwise.
int stepOption(const PluginOptions& options, const View& view, std::string_view plugin,
               const char* option, double fallback, bool allowAll);

// Node i of element e of a list.
Vec3 elementNode(const ElementList& list, std::size_t e, int i);
// Appends an element: its node coordinates, then its values (steps x nodes x components).
void appendElement(ElementList& list, std::span<const Vec3> nodes, std::span<const double> values);

// The simplices (as corner numbers) a shape is split into: a line, triangles or tetrahedra
// (quadrangles into 2, hexahedra into 6 around the diagonal 0-6, prisms into 3, pyramids
// into 2); none for points.
std::vector<std::vector<int>> simplexSplit(ElementShape shape);

}  // namespace geomesh::post::plugins
