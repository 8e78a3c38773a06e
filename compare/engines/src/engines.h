#pragma once
// The registry's rows: one factory per engine kind, one file each.
#include "compare/engines/engine_registry.h"
#include "compare/engines/external_engine.h"
#include "reference/bullet_engine.h"

namespace springcheck {

Engine mysimEngine();
Engine bulletEngine(reference::BulletEngine engine);
Engine externalEngine(const ExternalEngineSpec& spec);

}  // namespace springcheck
