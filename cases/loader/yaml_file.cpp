#include "cases/loader/yaml_file.hpp"

#include <yaml-cpp/depthguard.h>
#include <yaml-cpp/eventhandler.h>

#include <algorithm>
#include <sstream>
#include <string>

#include "cases/loader/limits.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

namespace {

// The bytes of one UTF-8 character that starts with `lead` (RFC 3629, section 4): how many bytes
// follow it, and the range its first follower must lie in (the others lie in 80..BF). The
// narrowed ranges refuse what a bare count of followers would let through: overlong forms
// (E0 80..9F, F0 80..8F; C0, C1 never lead), UTF-16 surrogates U+D800..DFFF (ED A0..BF), and code
// points past U+10FFFF (F4 90..BF; F5..FF never lead).
struct Utf8Lead {
    int follow = -1;  // -1: `lead` starts no character
    unsigned char low = 0x80, high = 0xbf;
};

Utf8Lead utf8_lead(unsigned char lead) {
    if (lead >= 0xc2 && lead <= 0xdf) return {1, 0x80, 0xbf};
    if (lead == 0xe0) return {2, 0xa0, 0xbf};
    if (lead == 0xed) return {2, 0x80, 0x9f};
    if (lead >= 0xe1 && lead <= 0xef) return {2, 0x80, 0xbf};
    if (lead == 0xf0) return {3, 0x90, 0xbf};
    if (lead == 0xf4) return {3, 0x80, 0x8f};
    if (lead >= 0xf1 && lead <= 0xf3) return {3, 0x80, 0xbf};
    return {};
}

// The length of the character at `text[i]` if it is a text character (UTF-8, no control byte
// but tab, LF and CR), else 0.
size_t text_character_length(const std::string& text, size_t i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c < 0x80) return (c >= 0x20 && c != 0x7f) || c == '\n' || c == '\r' || c == '\t' ? 1 : 0;
    const Utf8Lead lead = utf8_lead(c);
    if (lead.follow < 0 || text.size() - i <= static_cast<size_t>(lead.follow)) return 0;
    for (int k = 1; k <= lead.follow; ++k) {
        const auto b = static_cast<unsigned char>(text[i + static_cast<size_t>(k)]);
        const unsigned char low = k == 1 ? lead.low : 0x80, high = k == 1 ? lead.high : 0xbf;
        if (b < low || b > high) return 0;
    }
    return 1 + static_cast<size_t>(lead.follow);
}

}  // namespace

// Case files and override values are UTF-8 text: a NUL or other control byte (but tab and line
// ends) or a byte that is not part of a well-formed UTF-8 character means binary data, which
// yaml-cpp would otherwise report confusingly (or accept as a scalar).
size_t first_non_text_byte(const std::string& text) {
    for (size_t i = 0; i < text.size();) {
        const size_t length = text_character_length(text, i);
        if (length == 0) return i;
        i += length;
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

// Stops the parse at the start of a second document.
struct SecondDocument {
    YAML::Mark mark;
};
class DocumentStarts : public YAML::EventHandler {
  public:
    void OnDocumentStart(const YAML::Mark& mark) override {
        if (seen_) throw SecondDocument{mark};
        seen_ = true;
    }
    void OnDocumentEnd() override {}
    void OnNull(const YAML::Mark&, YAML::anchor_t) override {}
    void OnAlias(const YAML::Mark&, YAML::anchor_t) override {}
    void OnScalar(const YAML::Mark&, const std::string&, YAML::anchor_t,
                  const std::string&) override {}
    void OnSequenceStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                         YAML::EmitterStyle::value) override {}
    void OnSequenceEnd() override {}
    void OnMapStart(const YAML::Mark&, const std::string&, YAML::anchor_t,
                    YAML::EmitterStyle::value) override {}
    void OnMapEnd() override {}

  private:
    bool seen_ = false;
};

// Whether a line of `text` starts with a document marker, `---` or `...` (yaml-cpp reads one
// only at the start of a line).
bool has_document_marker(const std::string& text) {
    for (const char* marker : {"---", "..."}) {
        for (size_t at = text.find(marker); at != std::string::npos;
             at = text.find(marker, at + 1)) {
            if (at == 0 || text[at - 1] == '\n' || text[at - 1] == '\r') return true;
        }
    }
    return false;
}

}  // namespace

void check_one_document(const std::string& text, const YAML::Node& first, const std::string& file,
                        const std::string& what) {
    // yaml-cpp's Load reads the first document and drops the rest unread. Another document needs
    // a marker at the start of a line, or a first document that ends before the text does: a
    // flow collection or a scalar, or a block mapping indented past column 0 (yaml-cpp starts a
    // new document at the first key less indented than it). A block mapping at column 0 in a text
    // without markers, which is every catalog file, is one document: the second parse, most of
    // the time a case takes to load, is skipped for it.
    if (!has_document_marker(text) && first.IsMap() && first.Style() != YAML::EmitterStyle::Flow &&
        first.Mark().column == 0) {
        return;
    }
    std::istringstream in(text);
    DocumentStarts starts;
    try {
        YAML::Parser parser(in);
        while (parser.HandleNextDocument(starts)) {
        }
    } catch (const SecondDocument& second) {
        throw InputError(file + ":" + std::to_string(second.mark.line + 1) +
                         ": (yaml): a second YAML document starts here; a " + what +
                         " holds one document");
    } catch (const YAML::ParserException& e) {
        // Not in the first document, which Load has read: in the directives of a second one
        // (a document's own content is not parsed: its start is refused first).
        throw InputError(file + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): " + one_line(e.msg));
    }
}

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
    check_one_document(text, root, file, kind.name);
    if (root.IsNull()) throw InputError(file + ":1: (file): the " + kind.name + " is empty");
    if (!root.IsMap()) {
        throw InputError(file + ":" + std::to_string(root.Mark().line + 1) + ": (file): a " +
                         kind.name + " is a mapping of " + kind.contents);
    }
    return root;
}

}  // namespace rotbeam::cases
