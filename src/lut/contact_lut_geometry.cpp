// The geometry a contact LUT was built for (contact_lut.hpp: ContactLutGeometryDigest, CheckContactLutGeometry).
#include <cstdint>
#include <cstdio>
#include <cstring>

#include "conforma/contact_lut.hpp"
#include "conforma/error.hpp"
#include "conforma/geometry.hpp"

namespace conforma {

std::string ContactLutGeometryDigest(const WheelsetTrackGeometry& geometry) {
  // FNV-1a, 64 bit, over the bytes of every number of the fingerprint
  std::uint64_t hash = 14695981039346656037ull;
  for (double value : GeometryFingerprint(geometry)) {
    unsigned char bytes[sizeof(double)];
    std::memcpy(bytes, &value, sizeof value);
    for (unsigned char b : bytes) hash = (hash ^ b) * 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}

void CheckContactLutGeometryDigest(const ContactLut& lut, const std::string& geometry_digest) {
  const ContactLutHeader& h = lut.header;
  if (h.geometry_digest.empty()) return;  // a table written before the digest was recorded
  if (geometry_digest != h.geometry_digest)
    throw InputError("contact LUT: the table was built for another geometry (wheel '" + h.wheel_profile + "' on rail '" +
                     h.rail_profile + "', " + h.track + "): the profiles or the mounting given differ (digest " +
                     geometry_digest + ", table " + h.geometry_digest + ")");
}

void CheckContactLutGeometry(const ContactLut& lut, const WheelsetTrackGeometry& geometry) {
  if (lut.header.geometry_digest.empty()) return;  // (no hashing for a table without a digest)
  CheckContactLutGeometryDigest(lut, ContactLutGeometryDigest(geometry));
}

}  // namespace conforma
