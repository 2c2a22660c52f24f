#pragma once
namespace shadowlab::cli {
// `shadowlab info`: the shipped data folder it uses (exit 1 when none), GL vendor / renderer / version and the limits
// that matter to shadow maps.
int runInfo();
// `shadowlab scenes`: the built-in scenes with a line each.
int runScenes();
}  // namespace shadowlab::cli
