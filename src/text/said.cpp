#include "text/said.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <utility>

#include "text/describe.hpp"
#include "text/english_catalogue.hpp"
#include "text/message_catalogue.hpp"

namespace fl {

SaidArg arg(std::string name, double number) {
  return {std::move(name), number};
}
SaidArg arg(std::string name, int number) {
  return {std::move(name), static_cast<double>(number)};
}
SaidArg arg(std::string name, std::size_t number) {
  return {std::move(name), static_cast<double>(number)};
}
SaidArg arg(std::string name, std::string text) {
  return {std::move(name), std::move(text)};
}
SaidArg arg(std::string name, const char* text) {
  return {std::move(name), std::string(text)};
}
SaidArg arg(std::string name, Said message) {
  return {std::move(name), std::make_shared<const Said>(std::move(message))};
}

Said said(std::string id, std::vector<SaidArg> args) {
  return {std::move(id), std::move(args)};
}

double to_significant_digits(double x, int digits) {
  if (!std::isfinite(x)) return x;
  char text[64];
  std::snprintf(text, sizeof text, "%.*g", digits, x);
  return std::strtod(text, nullptr);
}

double to_decimal_places(double x, int places) {
  const double scale = std::pow(10.0, places);
  return std::round(x * scale) / scale;
}

std::string english(const Said& message) {
  static const MessageCatalogue catalogue = MessageCatalogue::parse(english_catalogue_text());
  std::map<std::string, std::string> values;
  for (const SaidArg& a : message.args) {
    if (const double* number = std::get_if<double>(&a.value))
      values[a.name] = describe(*number);
    else if (const std::string* text = std::get_if<std::string>(&a.value))
      values[a.name] = *text;
    else
      values[a.name] = english(*std::get<std::shared_ptr<const Said>>(a.value));
  }
  if (std::optional<std::string> text = catalogue.format(message.id, values)) return *text;
  return describe("(the message \"", message.id, "\", which the English catalogue lacks)");
}

}  // namespace fl
