// libFuzzer target: the .ini text through the project's strict reader (io::StrictIni: syntax, typed
// reads, unknown keys), the strict number parser and the "name:value, ..." list parser of libs/io.
#include <simp/io/NameValueList.h>
#include <simp/io/StrictIni.h>
#include <simp/io/StrictNumber.h>

#include "FuzzUtil.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    simp_fuzz::expectNoCrash([&] { simp::io::parseNameValueList(text, "[fuzz] list"); });
    simp_fuzz::expectNoCrash([&] { simp::io::parseNumber(text, "fuzz", -1e9, 1e9); });
    simp_fuzz::expectNoCrash([&] { simp::io::parseInteger(text, "fuzz", -1000, 1000); });
    simp_fuzz::expectNoCrash([&] {
        const simp::io::StrictIni ini(text, "fuzz.ini");
        std::vector<std::string> sections;
        ini.getAllSections(sections);
        for (const auto& s : sections) {
            ini.read_double(s, "duration_s", 1.0);
            ini.read_int(s, "count", 5);
            ini.read_bool(s, "flag", false);
            const auto list = ini.read_string(s, "confidence_thresholds", "");
            simp::io::parseNameValueList(list, "fuzz.ini [" + s + "] confidence_thresholds");
        }
        ini.checkUnknown();
    });
    return 0;
}
