// libFuzzer target: the .ini text (MRPT's CConfigFileMemory, then the project's known-key check)
// and the "name:value, ..." list parser of libs/io.
#include <mrpt/config/CConfigFileMemory.h>
#include <simp/io/IniKeys.h>
#include <simp/io/NameValueList.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    simp_fuzz::expectNoCrash([&] { simp::io::parseNameValueList(text, "[fuzz] list"); });
    simp_fuzz::expectNoCrash([&] {
        mrpt::config::CConfigFileMemory ini(text);
        std::vector<std::string> sections;
        ini.getAllSections(sections);
        for (const auto& s : sections) {
            simp::io::checkKnownKeys(ini, s, {"duration_s", "confidence_thresholds"}, "fuzz.ini");
            const auto list = ini.read_string(s, "confidence_thresholds", "");
            simp::io::parseNameValueList(list, "fuzz.ini [" + s + "] confidence_thresholds");
        }
    });
    return 0;
}
