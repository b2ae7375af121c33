#include "cli/word_choice.hpp"

#include "text/nearest_name.hpp"

namespace clrt {

CLI::Validator word_choice(const std::vector<std::string>& words) {
  const std::string listed = CLI::detail::join(words, ", ");
  return CLI::Validator(
      [words, listed](std::string& text) {
        const std::string lower = CLI::detail::to_lower(text);
        for (const std::string& word : words)
          if (CLI::detail::to_lower(word) == lower) {
            text = word;
            return std::string();
          }
        std::string message = text + " is not one of " + listed;
        if (const auto near = nearest_name(lower, words))
          message += " (did you mean " + *near + "?)";
        return message;
      },
      "{" + CLI::detail::join(words, ",") + "}");
}

}  // namespace clrt
