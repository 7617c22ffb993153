// The web API's declaration (api/api_fields.hpp) written out for the places that would list it by
// hand: the page's TypeScript types (web/src/api_types.ts) and docs/web-api.md's key tables.
// tools/generate-fields writes them between their markers; the fields_generated test checks them.
#pragma once

#include <vector>

#include "lab/listings/field_listing.hpp"

namespace fl::api {

// "web-api-types" and "web-api-keys".
std::vector<FieldListing> api_listings();

}  // namespace fl::api
