#pragma once
#include "viewer/viewer_session.h"

namespace viewer {

// Draws one engine's current state in the current GL context: the circle's orbit and point, or
// the colliders, then the cloth shaded (or the springs coloured by family), then the nodes
// (pinned ones red).
void drawEngine(const ViewerSession& session, const EngineView& e);

}  // namespace viewer
