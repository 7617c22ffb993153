// Whether a JSON body is what the web API's declaration (api/api_fields.hpp) says an object of a
// type is: every declared key there (unless optional), none undeclared, each value of its type,
// null only where the key is nullable. The test of serve's bodies uses it; the mock server's test
// has the same rules in JavaScript (web/tests/api_contract.mjs), over api_declaration_json().
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace fl::api {

// Each place `value` departs from `type` (a declared type, as api_fields.hpp writes types), as
// "PATH: what was expected, what was found"; none when it is what the declaration says. `path`
// names the value in the messages ("rig", "state.estimate").
std::vector<std::string> contract_problems(const nlohmann::json& value, const std::string& type,
                                           const std::string& path);

}  // namespace fl::api
