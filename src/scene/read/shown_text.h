// Text from an input file, quoted for an error message.
#pragma once

#include <string>
#include <string_view>

namespace candela {

// "text" shortened to 40 characters (then "..."), with quotes, backslashes and unprintable bytes
// written as \xNN, so that a binary file's bytes cannot garble the message.
std::string shownText(std::string_view text);

}  // namespace candela
