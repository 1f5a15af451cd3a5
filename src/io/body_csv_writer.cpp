#include "io/body_csv_writer.hpp"

#include <algorithm>
#include <charconv>
#include <numeric>
#include <string>

#include "io/csv_log.hpp"

namespace mpdem {

namespace {

void append_number(std::string& line, double v) {
  append_csv_number(line, v);
  line += ',';
}

}  // namespace

const char* body_csv_header() { return "time,id,clump,x,y,z,q0,q1,q2,q3,vx,vy,vz,wx,wy,wz,mass,I1,I2,I3"; }

Quat written_orientation(const Quat& q, const ClumpTemplate& clump) {
  const Quat& t = clump.shape.to_input;
  return quat_multiply(q, Quat{t.w, -t.x, -t.y, -t.z});  // the inverse of a unit quaternion: its conjugate
}

void write_bodies_csv(const std::filesystem::path& file, const Bodies& B, const std::vector<ClumpTemplate>& clumps,
                      double time) {
  std::vector<std::size_t> order(B.size());  // rows by ascending id, whatever the bodies' storage order
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&B](std::size_t a, std::size_t b) { return B.id[a] < B.id[b]; });
  write_csv_snapshot(file, body_csv_header(), order.size(), [&](std::string& line, std::size_t r) {
    const std::size_t b = order[r];
    const ClumpTemplate& tpl = clumps[static_cast<std::size_t>(B.clump[b])];
    append_number(line, time);
    char buf[24];  // the id as an integer: a double would round ids beyond 2^53
    line.append(buf, std::to_chars(buf, buf + sizeof buf, B.id[b]).ptr);
    ((line += ',') += tpl.name) += ',';
    const Quat q = written_orientation(B.q[b], tpl);
    for (const double v : {B.x[b].x, B.x[b].y, B.x[b].z, q.w, q.x, q.y, q.z, B.v[b].x, B.v[b].y, B.v[b].z, B.w[b].x,
                           B.w[b].y, B.w[b].z, B.mass[b], B.inertia[b].x, B.inertia[b].y, B.inertia[b].z})
      append_number(line, v);
    line.back() = '\n';
  });
}

}  // namespace mpdem
