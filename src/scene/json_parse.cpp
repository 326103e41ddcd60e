#include "scene/json_parse.h"

#include <utility>
#include <vector>

namespace raylab::scenefmt {
namespace {

class DomBuilder : public nlohmann::json_sax<Json> {
public:
    ParseResult result;

    bool null() override { return add(Json(nullptr)); }
    bool boolean(bool v) override { return add(Json(v)); }
    bool number_integer(number_integer_t v) override { return add(Json(v)); }
    bool number_unsigned(number_unsigned_t v) override { return add(Json(v)); }
    bool number_float(number_float_t v, const string_t&) override { return add(Json(v)); }
    bool string(string_t& v) override { return add(Json(std::move(v))); }
    bool binary(binary_t& v) override { return add(Json::binary(std::move(v))); }
    bool start_object(std::size_t) override { return open(Json::object()); }
    bool key(string_t& k) override {
        stack_.back().key = k;
        return true;
    }
    bool end_object() override { return close(); }
    bool start_array(std::size_t) override { return open(Json::array()); }
    bool end_array() override { return close(); }

    bool parse_error(std::size_t position, const std::string& lastToken,
                     const nlohmann::detail::exception& ex) override {
        result.ok = false;
        // `position` counts the characters read, so position - 1 is the offending character.
        result.errorOffset = position > 0 ? position - 1 : 0;
        if (ex.id == 406) {  // out_of_range.406: a number overflows a double (e.g. 1e999)
            result.errorOffset = position >= lastToken.size() ? position - lastToken.size() : 0;
            result.reason = "must be finite, got " + lastToken + " (too large for a double)";
            result.errorPath = currentPath();
        } else {
            result.reason = stripPrefix(ex.what());
        }
        return false;
    }

private:
    struct Level {
        Json* container;
        std::string key;  // objects: the key of the value that comes next
    };

    Json* place(Json&& v) {
        if (stack_.empty()) {
            result.doc = std::move(v);
            return &result.doc;
        }
        Level& top = stack_.back();
        if (top.container->is_array()) {
            top.container->push_back(std::move(v));
            return &top.container->back();
        }
        Json& slot = (*top.container)[top.key];
        slot = std::move(v);
        return &slot;
    }
    bool add(Json&& v) {
        place(std::move(v));
        return true;
    }
    bool open(Json&& v) {
        stack_.push_back(Level{place(std::move(v)), {}});
        return true;
    }
    bool close() {
        stack_.pop_back();
        return true;
    }
    JsonPath currentPath() const {
        // Enclosing arrays already hold the element being filled (the last one); the innermost
        // container has not received the offending value yet.
        JsonPath p;
        for (std::size_t i = 0; i < stack_.size(); ++i) {
            const Json& c = *stack_[i].container;
            if (!c.is_array()) p = p.key(stack_[i].key);
            else p = p.index(i + 1 < stack_.size() ? c.size() - 1 : c.size());
        }
        return p;
    }
    // "[json.exception.parse_error.101] parse error at line 1, column 5: syntax error ..." -> "syntax error ..."
    static std::string stripPrefix(std::string_view what) {
        if (auto bracket = what.find("] "); bracket != std::string_view::npos && what.front() == '[')
            what.remove_prefix(bracket + 2);
        if (what.starts_with("parse error")) {
            if (auto colon = what.find(": "); colon != std::string_view::npos) what.remove_prefix(colon + 2);
        }
        return std::string(what);
    }

    std::vector<Level> stack_;
};

} // namespace

ParseResult parseJson(std::string_view text) {
    DomBuilder builder;
    builder.result.ok = true;
    const bool ok = Json::sax_parse(text.begin(), text.end(), &builder, nlohmann::json::input_format_t::json,
                                    /*strict=*/true, /*ignore_comments=*/true);
    builder.result.ok = ok && builder.result.ok;
    return std::move(builder.result);
}

} // namespace raylab::scenefmt
