// bridge/fwd.hpp: forward declarations of the bridge module (geometry -> facts).
#pragma once

namespace qm::bridge {
class SceneAtConfig;
}  // namespace qm::bridge
