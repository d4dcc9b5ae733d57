#include "session/notices.hpp"

namespace psb::app {

const char* logPrefix(Notice::Level level) {
    switch (level) {
        case Notice::Level::Warning:
            return "[W] ";
        case Notice::Level::Error:
            return "[E] ";
        case Notice::Level::Info:
            break;
    }
    return "[I] ";
}

}  // namespace psb::app
