// test-links: pipeline
// One spelling of the user-visible statuses (issue 13, item 11): "no_contact" and "not_converged" in every
// to_string that reaches a report, CSV, JSON or the C API (they were "no contact", "no-contact", "not-converged").
#include <gtest/gtest.h>

#include <string>

#include "conforma/bem_reference.hpp"
#include "conforma/contact_candidates.hpp"
#include "conforma/geometry.hpp"
#include "conforma/hertz.hpp"
#include "conforma/wheel_contact.hpp"

namespace {

using namespace conforma;

TEST(StatusSpelling, NoContactAndNotConvergedAreSpelledOneWay) {
  for (const std::string& s : {std::string(to_string(WheelContactStatus::NoContact)),
                              std::string(to_string(EquilibriumStatus::NoContact)),
                              std::string(to_string(CandidateStatus::NoContact)),
                              std::string(to_string(BemStatus::NoContact)), std::string(to_string(HertzStatus::NoContact))})
    EXPECT_EQ(s, "no_contact");
  for (const std::string& s : {std::string(to_string(WheelContactStatus::NotConverged)),
                              std::string(to_string(EquilibriumStatus::NotConverged)),
                              std::string(to_string(BemStatus::NotConverged))})
    EXPECT_EQ(s, "not_converged");
  EXPECT_EQ(std::string(to_string(ContactStatus::NoOverlap)), "no_overlap");
}

}  // namespace
