// libFuzzer target: the rawlog reader (simp::obs::readRawlog over a memory stream), which reads
// our CObservationObjects3D and MRPT's containers through a BoundedArchive.
#include <mrpt/io/CMemoryStream.h>
#include <simp/obs/RawlogReader.h>
#include <simp/obs/registerAllClasses.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    mrpt::io::CMemoryStream in;
    in.assignMemoryNotOwn(data, size);
    simp_fuzz::expectNoCrash([&] { simp::obs::readRawlog(in, size, "fuzz.rawlog"); });
    return 0;
}
