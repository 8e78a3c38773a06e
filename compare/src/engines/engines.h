#pragma once
// The registry's rows: one factory per engine kind, one file each.
#include "compare/engine_registry.h"
#include "compare/external_engine.h"
#include "reference/bullet_engine.h"

namespace springcheck {

Engine mysimEngine();
Engine bulletEngine(reference::BulletEngine engine);
Engine externalEngine(const ExternalEngineSpec& spec);

}  // namespace springcheck
