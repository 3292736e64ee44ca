// The head of a case's JSON document (case_document.hpp).
#include "case_document.hpp"

#include "number_format.hpp"
#include "tolip_ground/version.hpp"

namespace tolip::ground::report_detail {

nlohmann::ordered_json case_document(const std::string& deck_path, const DeckListingOptions& listing,
                                     Status status) {
  nlohmann::ordered_json document = nlohmann::ordered_json::object();
  document["program"] = "tolip";
  document["version"] = version_string();
  document["deck"] = deck_path;
  document["title"] = card_text(listing.title);
  document["case_heading"] = card_text(listing.case_heading);
  document["date"] = card_text(listing.date);
  document["status"] = status_name(status);
  document["status_message"] = status_message(status);
  return document;
}

}  // namespace tolip::ground::report_detail
