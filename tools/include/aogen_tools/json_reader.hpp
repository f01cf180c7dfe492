// aogen_tools/json_reader.hpp — reading JSON input files with errors that say where.
//
// Shared by every tool that reads JSON: the `aogen` command line (struct files, variant
// specs), the scene files of bench/scenes and the report. A json_reader is a view of one
// JSON value plus its path in the file ("params.json: members[2].count"), so every
// complaint names the file, the field, the value and what would be valid. Unknown keys are errors too: a typo ("cout") should
// not be silently ignored.
#pragma once

#include <aogen/error.hpp>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <initializer_list>
#include <string>

namespace aogen::tools {

class json_reader {
public:
    json_reader(const nlohmann::json& value, std::string path) : value_(&value), path_(std::move(path)) {}

    // Parses `text`; `source` names it in messages (a file name).
    static nlohmann::json parse(const std::string& text, const std::string& source)
    {
        try {
            return nlohmann::json::parse(text);
        } catch (const nlohmann::json::parse_error& e) {
            fail(source, std::string("is not valid JSON: ") + e.what(), "valid: a JSON document");
        }
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
            if (!known) fail(path_ + "." + item.key(), "is not a known key", "valid: " + valid);
        }
    }

    json_reader field(const char* key) const
    {
        require_object();
        if (!value_->contains(key)) fail(path_ + "." + key, "is missing", "it is required");
        return json_reader((*value_)[key], path_ + "." + key);
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
        if (!value_->is_number_integer()) fail(path_, value_->dump() + " is not an integer", valid);
        if (value_->is_number_unsigned()) {
            const uint64_t v = value_->get<uint64_t>();
            if (v < lo || v > hi) fail(path_, std::to_string(v) + " is out of range", valid);
            return static_cast<uint32_t>(v);
        }
        fail(path_, value_->dump() + " is out of range", valid);
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
