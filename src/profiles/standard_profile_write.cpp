// Writes the generated standard profiles as Simpack files (the committed copies in profiles/).
#include "conforma/profile_io.hpp"
#include "conforma/standard_profiles.hpp"

namespace conforma {

void WriteStandardProfiles(const std::string& dir) {
  SaveProfileSimpack(MakeS1002(), dir + "/S1002.prw");
  for (RailSection r : {RailSection::R60E1, RailSection::R54E1, RailSection::R50E6, RailSection::R50E4}) {
    const std::string base = dir + "/" + to_string(r);
    SaveProfileSimpack(MakeRail(r, 0.0), base + ".prr");
    SaveProfileSimpack(MakeRail(r, rail_inclination_1in40()), base + "_1in40.prr");
    SaveProfileSimpack(MakeRail(r, rail_inclination_1in20()), base + "_1in20.prr");
  }
}

}  // namespace conforma
