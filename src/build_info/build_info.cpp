#include "build_info.hpp"

#include "build_revision.hpp"

namespace psb {

std::string_view projectVersion() {
    return PSB_PROJECT_VERSION;
}

std::string_view gitRevision() {
    return PSB_GIT_REVISION;
}

std::string versionLine(std::string_view program) {
    std::string line(program);
    line += ' ';
    line += projectVersion();
    if (!gitRevision().empty()) {
        line += " (git ";
        line += gitRevision();
        line += ')';
    }
    return line;
}

}  // namespace psb
