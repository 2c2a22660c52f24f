#pragma once
// The editor's player of the scene's animations (the Timeline panel drives it): the time advances while playing,
// looping over the chosen animations' span or stopping at its end, and the shown scene is the loaded one posed at
// the settings' animation.play and animation.time whenever they change (a new scene object: the renderer and any
// running measurement keep the pose they started with).
#include "editor/editor_state.h"
#include "scene/scene_animation.h"

namespace shadowlab::editor {

// Moves animation.time by dt x speed while playing; stops at the end when not looping.
void advanceTimeline(EditorState& state, double dtSeconds);

// Replaces state.scene by timeline.rest posed at the settings' animation when they differ from the pose shown; an
// animation.play the scene lacks is said once (timeline.error) and the file's pose is shown. true when replaced.
bool poseShownScene(EditorState& state);

// The span of the animations animation.play chooses ({0, 0} when none or unknown).
AnimationSpan chosenSpan(const EditorState& state);

}  // namespace shadowlab::editor
