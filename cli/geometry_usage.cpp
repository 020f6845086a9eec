// cli/geometry_usage.cpp: the usage lines of the geometry commands (cli/geometry_usage.hpp).
#include "geometry_usage.hpp"

namespace qm::cli {

const char* metric_usage() noexcept {
    return "       qm-atms --emit-def METRIC-SCENE [CONFIG]   Alex scene of a metric scene at CONFIG ('part=value, ...')\n"
           "       qm-atms --places METRIC-SCENE [--json] [--svg DIR] [--cache DIR | --no-cache]\n"
           "                                                  place vocabulary of each kinematic pair\n";
}

const char* draw_usage() noexcept {
    return "       qm-atms draw METRIC-SCENE [--config 'PART=VALUE, ...' | --place A--B:ID | --history 'STATE STATE ...' [--columns N]]\n"
           "                    --svg FILE [--size WxH] [--cache DIR | --no-cache]\n"
           "                                                  the parts drawn at a configuration, at a place, or along a history\n";
}

const char* explore_usage() noexcept {
    return "       qm-atms explore METRIC-SCENE -o DIR [--no-envision | --path 'DESC; DESC; ...'... [--avoid 'DESC']...]\n"
           "                       [--cache DIR | --no-cache]  a page (DIR/index.html) to explore the places and states\n";
}

const char* envision_usage() noexcept {
    return "       qm-atms envision METRIC-SCENE [--table | --json] [--max-states N] [--max-memory SIZE]\n"
           "                        [--without 'Force PART [CAUSE]']... [--from STATE] [--next STATE] [--previous STATE]\n"
           "                        [--path 'DESC; DESC; ...' [--avoid 'DESC']...]\n"
           "                        [--why-not 'STATE -> STATE'] [--dot FILE] [--svg FILE]\n"
           "                        [--cache DIR | --no-cache] [--rules DIR] [--stats] [--verify]\n"
           "                                                  the envisionment: states, transitions, cycles (docs/ENVISION.md)\n";
}

}  // namespace qm::cli
