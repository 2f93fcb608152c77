#include "cases/loader/yaml_file.hpp"

#include <yaml-cpp/depthguard.h>

#include <algorithm>
#include <string>

#include "cases/loader/limits.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

// Case files and override values are UTF-8 text: a NUL or other control byte (but tab and line
// ends) or a malformed UTF-8 sequence means binary data, which yaml-cpp would otherwise report
// confusingly (or accept as a scalar). Returns the offset of the first such byte, or npos.
size_t first_non_text_byte(const std::string& text) {
    for (size_t i = 0; i < text.size(); ++i) {
        const auto c = static_cast<unsigned char>(text[i]);
        int follow = 0;
        if (c == 0 || (c < 0x20 && c != '\n' && c != '\r' && c != '\t') || c == 0x7f) {
            follow = -1;
        } else if (c >= 0x80) {
            follow = (c >= 0xc2 && c <= 0xdf)   ? 1
                     : (c >= 0xe0 && c <= 0xef) ? 2
                     : (c >= 0xf0 && c <= 0xf4) ? 3
                                                : -1;
            for (int k = 1; follow > 0 && k <= follow; ++k) {
                if (i + k >= text.size() ||
                    (static_cast<unsigned char>(text[i + k]) & 0xc0) != 0x80) {
                    follow = -1;
                }
            }
        }
        if (follow < 0) return i;
        i += static_cast<size_t>(follow);
    }
    return std::string::npos;
}

namespace {

void check_text(const std::string& text, const std::string& file, const YamlFileKind& kind) {
    const size_t at = first_non_text_byte(text);
    if (at == std::string::npos) return;
    const auto line =
        1 + std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n');
    throw InputError(file + ":" + std::to_string(line) + ": (file): not a text " + kind.name +
                     " (control or non-UTF-8 byte at offset " + std::to_string(at) + ")");
}

}  // namespace

YAML::Node parse_yaml_file(const std::string& text, const std::string& file,
                           const YamlFileKind& kind) {
    if (text.size() > kMaxFileBytes) {
        throw InputError(file + ":1: (file): larger than " + std::to_string(kMaxFileBytes) +
                         " bytes (" + kind.size_limit + ")");
    }
    check_text(text, file, kind);
    check_yaml_shape(text, file);
    YAML::Node root;
    try {
        root = YAML::Load(text);
    } catch (const YAML::DeepRecursion& e) {
        // yaml-cpp's own guard (2000 levels, before the tree exists; its message is "bad file").
        throw InputError(file + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): nested deeper than " + std::to_string(kMaxYamlDepth) +
                         " levels (the limit of a " + kind.name + ")");
    } catch (const YAML::ParserException& e) {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): " + one_line(e.msg));
    }
    if (root.IsNull()) throw InputError(file + ":1: (file): the " + kind.name + " is empty");
    if (!root.IsMap()) {
        throw InputError(file + ":" + std::to_string(root.Mark().line + 1) + ": (file): a " +
                         kind.name + " is a mapping of " + kind.contents);
    }
    return root;
}

}  // namespace rotbeam::cases
