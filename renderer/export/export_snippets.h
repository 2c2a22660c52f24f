#pragma once
// Ready-to-paste text for one API (D3D12, D3D11, Vulkan, OpenGL) or JSON, from the numbers in ShadowExport. Each
// snippet states its conventions in comments: depth range, reversed-Z, the format's minimum resolvable difference r,
// D3D's float-format rule, the winding, the normal offset in world units and the sampler / filter.
#include "export/shadow_export.h"

#include <string>

namespace shadowlab {

// One light's snippet: its state, every view's matrix and its shader code.
std::string exportSnippet(const ShadowExport& values, ExportFormat format);
// Every light of the set, each section naming its light (a light without a shadow is listed as such); a set where
// nothing casts says so.
std::string exportSnippet(const ShadowExportSet& set, ExportFormat format);

}  // namespace shadowlab
