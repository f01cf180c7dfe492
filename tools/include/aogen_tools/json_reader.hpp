// aogen_tools/json_reader.hpp — reading JSON input files with errors that say where.
//
// Shared by every tool that reads JSON: the `aogen` command line (struct files, variant
// specs), the scene files of scenes and the report. A json_reader is a view of one
// JSON value plus its path in the file ("params.json.members[2].count"), so every
// complaint names the file, the field, the value and what would be valid. Unknown keys
// are errors too: a typo ("cout") should not be silently ignored.
//
// parse() checks the document's shape before it builds it (detail::shape_check, a SAX
// pass): at most max_depth levels of arrays and objects (a file of 100 000 nested
// brackets is refused in one line, before anything recurses over it), no key twice in one
// object (JSON leaves that undefined; "last wins" would hide a mistake), no number beyond
// a double (1e400) — each error naming the path where it happened. Values quoted in
// messages go through describe(): a scalar short and escaped, an array or object by its
// size, never the whole value.
#pragma once

#include <aogen/error.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <set>
#include <string>
#include <vector>

namespace aogen::tools {

// Arrays and objects nested deeper than this are refused: aogen's formats need 5.
inline constexpr size_t json_max_depth = 64;

// A JSON value as an error message quotes it: numbers and literals as written, strings
// through aogen::quoted (escaped, at most 80 characters), arrays and objects by their size.
inline std::string describe(const nlohmann::json& v)
{
    if (v.is_array()) return "an array of " + std::to_string(v.size()) + (v.size() == 1 ? " value" : " values");
    if (v.is_object()) return "an object of " + std::to_string(v.size()) + (v.size() == 1 ? " key" : " keys");
    if (v.is_string()) return quote(v.get_ref<const std::string&>());
    return v.dump();
}

// `parent` + "." + key for a key of letters, digits and '_' (at most 64 of them), else
// `parent` + "[" + quote(key) + "]": a key is user text too, and a path must stay short
// and printable.
inline std::string key_path(const std::string& parent, const std::string& key)
{
    bool plain = !key.empty() && key.size() <= 64;
    for (char c : key) plain = plain && ((c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_');
    return plain ? parent + "." + key : parent + "[" + quote(key, 32) + "]";
}

namespace detail {

// The SAX pass of json_reader::parse: depth, duplicate keys and overflowing numbers, with
// the path ("scene.json.geometry[2].normal") of where each is found.
class shape_check : public nlohmann::json_sax<nlohmann::json> {
public:
    explicit shape_check(std::string source) : source_(std::move(source)) {}

    bool null() override { return value(); }
    bool boolean(bool) override { return value(); }
    bool number_integer(number_integer_t) override { return value(); }
    bool number_unsigned(number_unsigned_t) override { return value(); }
    bool number_float(number_float_t x, const string_t& text) override
    {
        value();
        if (!std::isfinite(x)) fail(path(), quote(text) + " is beyond the range of a double", "valid: a number of magnitude below 1.8e308");
        return true;
    }
    bool string(string_t&) override { return value(); }
    bool binary(binary_t&) override { return value(); }
    bool start_object(std::size_t) override { return open(true); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(string_t& k) override
    {
        frame& f = frames_.back();
        f.key = k;
        if (!f.keys.insert(k).second) fail(path(), "appears twice in one object", "valid: each key once");
        return true;
    }
    bool parse_error(std::size_t, const std::string& token, const nlohmann::detail::exception& e) override
    {
        if (e.id == 406) // out_of_range.406: the lexer's "number overflow", before any number_float
            fail(path(), quote(token) + " is beyond the range of a double", "valid: a number of magnitude below 1.8e308");
        std::string what = e.what();
        const size_t tag = what.find("] "); // "[json.exception.parse_error.101] parse error at line 1, ..."
        fail(source_, "is not valid JSON: " + (tag == std::string::npos ? what : what.substr(tag + 2)), "valid: a JSON document");
    }

private:
    struct frame {
        bool object = false;
        std::set<std::string> keys;
        std::string key; // objects: the current key
        size_t index = 0; // arrays: elements so far
    };

    // A value begins: in an array, it is the next element.
    bool value()
    {
        if (!frames_.empty() && !frames_.back().object) ++frames_.back().index;
        return true;
    }
    bool open(bool object)
    {
        value();
        if (frames_.size() >= json_max_depth)
            fail(path(), "is nested deeper than " + std::to_string(json_max_depth) + " levels",
                 "valid: at most " + std::to_string(json_max_depth) + " levels of arrays and objects");
        frames_.push_back({object, {}, "", 0});
        return true;
    }
    bool close()
    {
        frames_.pop_back();
        return true;
    }
    // "source.key[3].key": the place the parse is at. A run of arrays in arrays is written
    // "[0][...]" past its first two levels, so a path through 100 000 of them stays short.
    std::string path() const
    {
        std::string p = source_;
        size_t run = 0; // consecutive array levels so far
        for (const frame& f : frames_) {
            run = f.object ? 0 : run + 1;
            if (f.object && !f.key.empty()) p = key_path(p, f.key);
            else if (!f.object && f.index > 0 && run <= 2) p += "[" + std::to_string(f.index - 1) + "]";
            else if (!f.object && run == 3) p += "[...]";
        }
        return p;
    }

    std::string source_;
    std::vector<frame> frames_;
};

} // namespace detail

class json_reader {
public:
    json_reader(const nlohmann::json& value, std::string path) : value_(&value), path_(std::move(path)) {}

    // Parses `text`, its shape checked first (see the header comment); `source` names it
    // in messages (a file name).
    static nlohmann::json parse(const std::string& text, const std::string& source)
    {
        detail::shape_check check(source);
        nlohmann::json::sax_parse(text, &check);
        return nlohmann::json::parse(text); // cannot fail now: the same text passed the SAX pass
    }

    const std::string& path() const { return path_; }
    size_t size() const { return value_->size(); }
    bool has(const char* key) const { return value_->is_object() && value_->contains(key); }

    void require_object() const
    {
        if (!value_->is_object()) fail(path_, "is " + kind() + ", not an object", "valid: { ... }");
    }

    void only_keys(std::initializer_list<const char*> keys) const
    {
        require_object();
        for (const auto& item : value_->items()) {
            bool known = false;
            std::string valid;
            for (const char* k : keys) {
                known = known || item.key() == k;
                valid += (valid.empty() ? "" : ", ") + std::string(k);
            }
            if (!known) fail(key_path(path_, item.key()), "is not a known key", "valid: " + valid);
        }
    }

    json_reader field(const char* key) const
    {
        require_object();
        if (!value_->contains(key)) fail(key_path(path_, key), "is missing", "valid: a value here is required");
        return json_reader((*value_)[key], key_path(path_, key));
    }

    json_reader at(size_t index) const { return json_reader((*value_)[index], path_ + "[" + std::to_string(index) + "]"); }

    std::string string(const char* key) const { return field(key).as_string(); }

    json_reader array(const char* key) const
    {
        const json_reader f = field(key);
        if (!f.value_->is_array()) fail(f.path_, "is " + f.kind() + ", not an array", "valid: [ ... ]");
        return f;
    }

    uint32_t unsigned_integer(const char* key, uint32_t lo, uint32_t hi) const { return field(key).as_unsigned(lo, hi); }

    // This value as an integer in [lo, hi].
    uint32_t as_unsigned(uint32_t lo, uint32_t hi) const
    {
        const std::string valid = "valid: an integer " + std::to_string(lo) + ".." + std::to_string(hi);
        if (!value_->is_number_integer()) fail(path_, describe(*value_) + " is not an integer", valid);
        if (value_->is_number_unsigned()) {
            const uint64_t v = value_->get<uint64_t>();
            if (v < lo || v > hi) fail(path_, std::to_string(v) + " is out of range", valid);
            return static_cast<uint32_t>(v);
        }
        fail(path_, describe(*value_) + " is out of range", valid);
    }

    // This value as a string.
    std::string as_string() const
    {
        if (!value_->is_string()) fail(path_, "is " + kind() + ", not a string", "valid: \"...\"");
        return value_->get<std::string>();
    }

    // This value as a number.
    double as_number() const
    {
        if (!value_->is_number()) fail(path_, "is " + kind() + ", not a number", "valid: a number");
        return value_->get<double>();
    }

    double number(const char* key) const
    {
        const json_reader f = field(key);
        if (!f.value_->is_number()) fail(f.path_, "is " + f.kind() + ", not a number", "valid: a number");
        return f.value_->get<double>();
    }

    bool boolean(const char* key) const
    {
        const json_reader f = field(key);
        if (!f.value_->is_boolean()) fail(f.path_, "is " + f.kind() + ", not true or false", "valid: true, false");
        return f.value_->get<bool>();
    }

private:
    const nlohmann::json* value_;
    std::string path_;

    std::string kind() const
    {
        return std::string(value_->type_name()) == "null" ? "null" : std::string("a ") + value_->type_name();
    }
};

} // namespace aogen::tools
