// libFuzzer target: the binary CObjectMap reader (CObjectMap::serializeFrom through a
// BoundedArchive). Inputs whose object header is not CObjectMap's are skipped, so the fuzzer
// spends its time in our reader rather than in every registered MRPT class.
#include <mrpt/io/CMemoryStream.h>
#include <simp/maps/CObjectMap.h>
#include <simp/obs/BoundedArchive.h>

#include <cstring>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const std::string name = "simp::maps::CObjectMap";
    if (size < name.size() + 2 || data[0] != (0x80 | name.size()) ||
        std::memcmp(data + 1, name.data(), name.size()) != 0)
        return 0;
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(data, size);
    simp::obs::BoundedArchive archive(in, size, "fuzz_map.bin");
    simp_fuzz::expectNoCrash([&] { archive.readObjectGuarded(); });
    return 0;
}
