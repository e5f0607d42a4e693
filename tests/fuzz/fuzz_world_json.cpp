// libFuzzer target: objects.json of a world directory (simp::world::loadObjectMap).
#include <simp/world/ObjectMapData.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const auto path = simp_fuzz::writeInput("objects.json", data, size);
    simp_fuzz::expectNoCrash([&] { simp::world::loadObjectMap(path); });
    return 0;
}
