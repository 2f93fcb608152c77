// The YAML shape check (limits.hpp): one pass over the parser's events, before yaml-cpp builds a
// tree. Every node's size with its aliases expanded and its height are known when it ends, so an
// alias adds its anchor's size and height without expanding anything; an alias whose anchor is
// still open is inside the node it names — a cycle.
#include <yaml-cpp/eventhandler.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <map>
#include <sstream>
#include <vector>

#include "cases/loader/limits.hpp"
#include "cases/loader/yaml_reader.hpp"
#include "core/errors.hpp"

namespace rotbeam::cases {

namespace {

class ShapeCheck : public YAML::EventHandler {
  public:
    explicit ShapeCheck(const std::string& file) : file_(file) {}

    void OnDocumentStart(const YAML::Mark&) override {}
    void OnDocumentEnd() override {}
    void OnAnchor(const YAML::Mark&, const std::string& name) override { pending_name_ = name; }
    void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override { leaf(mark, anchor); }
    void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  const std::string&) override {
        leaf(mark, anchor);
    }
    void OnAlias(const YAML::Mark& mark, YAML::anchor_t anchor) override {
        const auto it = anchors_.find(anchor);
        if (it == anchors_.end() || it->second.open) {
            const std::string name = it == anchors_.end() ? std::string() : it->second.name;
            fail(mark, "alias *" + name +
                           " is inside the node its anchor names (a recursive alias, which "
                           "would expand forever)");
        }
        add(mark, it->second.size, it->second.height);
    }
    void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                         YAML::EmitterStyle::value) override {
        open(mark, anchor);
    }
    void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                    YAML::EmitterStyle::value) override {
        open(mark, anchor);
    }
    void OnSequenceEnd() override { close(); }
    void OnMapEnd() override { close(); }

  private:
    struct Anchor {
        std::string name;
        bool open = true;
        long size = 0;
        int height = 0;
    };
    struct Open {
        YAML::anchor_t anchor;
        YAML::Mark mark;
        long size = 1;   // this node and its children so far, aliases expanded
        int height = 1;  // levels of collections below and including it
    };

    [[noreturn]] void fail(const YAML::Mark& mark, const std::string& problem) const {
        throw InputError(file_ + ":" + std::to_string(mark.line + 1) + ": (yaml): " + problem);
    }

    void name_anchor(YAML::anchor_t anchor) {
        if (anchor == YAML::NullAnchor) return;
        anchors_[anchor] = Anchor{pending_name_, true, 0, 0};
        pending_name_.clear();
    }

    // A node of `size` nodes and `height` levels placed in the open collection (or as the root).
    void add(const YAML::Mark& mark, long size, int height) {
        total_ += size;
        if (total_ > kMaxYamlNodes) {
            fail(mark, "more than " + std::to_string(kMaxYamlNodes) +
                           " nodes with aliases expanded (the limit of a case file; an alias "
                           "repeats its anchor's whole node)");
        }
        const int depth = static_cast<int>(stack_.size()) + height;
        if (depth > kMaxYamlDepth) {
            fail(mark, "nested deeper than " + std::to_string(kMaxYamlDepth) +
                           " levels (the limit of a case file)");
        }
        if (!stack_.empty()) {
            stack_.back().size += size;
            stack_.back().height = std::max(stack_.back().height, height + 1);
        }
    }

    void leaf(const YAML::Mark& mark, YAML::anchor_t anchor) {
        name_anchor(anchor);
        add(mark, 1, 0);
        if (anchor != YAML::NullAnchor) anchors_[anchor] = {anchors_[anchor].name, false, 1, 0};
    }

    void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
        name_anchor(anchor);
        // Counted now (so that a deep or huge document stops at once), its height at 1 level.
        add(mark, 1, 1);
        stack_.push_back(Open{anchor, mark});
    }

    void close() {
        const Open done = stack_.back();
        stack_.pop_back();
        // Its children are already in the total and in the parent's size; only the parent's
        // size and height still miss them.
        if (!stack_.empty()) {
            stack_.back().size += done.size - 1;
            stack_.back().height = std::max(stack_.back().height, done.height + 1);
        }
        if (done.anchor != YAML::NullAnchor) {
            Anchor& a = anchors_[done.anchor];
            a.open = false;
            a.size = done.size;
            a.height = done.height;
        }
    }

    std::string file_;
    std::string pending_name_;
    std::map<YAML::anchor_t, Anchor> anchors_;
    std::vector<Open> stack_;
    long total_ = 0;
};

}  // namespace

void check_yaml_shape(const std::string& text, const std::string& file) {
    // Without an anchor there is no alias (an alias to an undefined anchor is a parse error): the
    // tree is then no larger than the text and has no cycle, and its nesting is checked when it is
    // indexed (YamlReader::index). The pass is skipped, since the parse is most of the time a case
    // takes to load (docs/performance.md, start-up).
    if (text.find('&') == std::string::npos) return;
    std::istringstream in(text);
    ShapeCheck check(file);
    try {
        YAML::Parser parser(in);
        parser.HandleNextDocument(check);
    } catch (const YAML::ParserException& e) {
        throw InputError(file + ":" + std::to_string(e.mark.line + 1) +
                         ": (yaml): " + one_line(e.msg));
    }
}

}  // namespace rotbeam::cases
