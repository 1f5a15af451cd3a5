#pragma once
// Body CSV snapshots (docs/output.md "Body CSV"): every clump body at one time, one row each, read
// back as a body CSV by a [[particles]] entry with `clump = "name"` (scene/clump_reader.hpp), which
// skips the columns that only describe the body (time, clump, mass, I1, I2, I3). Numbers as in
// io/csv_log.hpp: 17 significant digits, integral values as integers.
#include <filesystem>
#include <vector>

#include "model/clump_template.hpp"
#include "state/bodies.hpp"

namespace mpdem {

// The header line without its line break:
// time,id,clump,x,y,z,q0,q1,q2,q3,vx,vy,vz,wx,wy,wz,mass,I1,I2,I3.
const char* body_csv_header();

// The orientation a body CSV row gives for a body whose principal frame has orientation q: the
// template's frame as written -> world, q * to_input^-1 (a row's q0..q3 are turned into the
// principal frame's as q_row * to_input: model/body_members.hpp add_body).
Quat written_orientation(const Quat& q, const ClumpTemplate& clump);

// Writes every body at one time as a complete CSV file, atomically, one row per body in ascending
// id order: time (s), id, the template's name, the centre of mass (m), the orientation as written
// (written_orientation), velocity (m/s), angular velocity (rad/s, world), mass (kg) and principal
// moments (kg m^2). `clumps`: the scene's templates (Bodies::clump indexes them).
void write_bodies_csv(const std::filesystem::path& file, const Bodies& bodies, const std::vector<ClumpTemplate>& clumps,
                      double time);

}  // namespace mpdem
