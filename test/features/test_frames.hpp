#pragma once
// Frames for the feature tests, and the check that a call is refused with a message that names
// what it should.

#include <gtest/gtest.h>

#include <initializer_list>
#include <opencv2/core/mat.hpp>
#include <random>
#include <stdexcept>
#include <string>
#include <string_view>

namespace safecell::test {

// Every pixel uniform in [low, high].
cv::Mat uniform_frame(std::mt19937_64& rng, cv::Size size, int low, int high);

// One of several kinds, picked at random: uniform noise, low-contrast noise, two levels, a
// constant (0, 255 or any), a gradient with noise, random rectangles; sometimes noise-cut.
cv::Mat random_frame(std::mt19937_64& rng, cv::Size size);

// `call` throws std::invalid_argument whose message contains every one of `parts`.
template <typename Call>
void expect_invalid_argument(Call&& call, std::initializer_list<std::string_view> parts) {
  try {
    call();
    ADD_FAILURE() << "no std::invalid_argument thrown";
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    for (const std::string_view part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "message \"" << message << "\" lacks \"" << part << "\"";
    }
  }
}

}  // namespace safecell::test
