// A message the lab says to a person: its id in the message catalogues (assets/locales/LANG.ftl,
// the one file a translator edits) and its values, so that each front end says it in its
// reader's language. The command line, Python and the logs say it in English, from en.ftl as it
// was when the lab was built: the English text has one home, the catalogue.
#pragma once

#include <memory>
#include <string>
#include <variant>
#include <vector>

namespace fl {

struct Said;

// One value of a message, by the name its pattern uses (`{ $spacing_mm }`): a number (in the
// unit the name says), a text said as it is (a key, a file's name), or another message said in
// the same language ("the roller spacing l").
struct SaidArg {
  std::string name;
  std::variant<double, std::string, std::shared_ptr<const Said>> value;
};

struct Said {
  std::string id;  // e.g. "lab-rollers-overlap"
  std::vector<SaidArg> args = {};
};

SaidArg arg(std::string name, double number);
SaidArg arg(std::string name, int number);
SaidArg arg(std::string name, std::size_t number);
SaidArg arg(std::string name, std::string text);
SaidArg arg(std::string name, const char* text);
SaidArg arg(std::string name, Said message);

Said said(std::string id, std::vector<SaidArg> args = {});

// A measured value as a message shows it, rounded before it is said so that every language shows
// the same digits: to `digits` significant digits, or to `places` decimal places.
double to_significant_digits(double x, int digits);
double to_decimal_places(double x, int places);

// The message in English, its numbers written as describe() writes them (six significant
// digits). A message en.ftl lacks says so in its text (the catalogues' test keeps every id the
// lab says in en.ftl).
std::string english(const Said& message);

}  // namespace fl
