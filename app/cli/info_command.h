#pragma once
namespace shadowlab::cli {
// `shadowlab info`: GL vendor / renderer / version and the limits that matter to shadow maps.
int runInfo();
// `shadowlab scenes`: the built-in scenes with a line each.
int runScenes();
}  // namespace shadowlab::cli
