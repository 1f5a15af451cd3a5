#pragma once
// Contact snapshots ([output] contacts_every; docs/output.md "Contact snapshots"): every
// particle-particle and particle-barrier contact of the last evaluation, as a VTK UnstructuredGrid
// (.vtu, one line cell per contact: force chains in ParaView; meshio reads .vtu, not .vtp) and as CSV. Both written
// atomically.
#include <filesystem>
#include <span>

#include "model/params.hpp"
#include "output/contact_list.hpp"

namespace mpdem {

// One VTK_LINE per contact from the first particle's centre to the other's centre (a pair: its
// image across a periodic boundary, so the line is the branch vector) or to the contact point (a
// barrier contact). CellData: first, second (-1 for a barrier), element (-1 for a pair), point,
// normal, overlap, normal_force, tangential_force, force_magnitude, normal_force_magnitude,
// sliding, with `bodies` (a scene with clumps) first_body, second_body (the members' body ids,
// -1 for a free sphere or no second particle), and with `cohesion` (a scene whose contacts keep a
// cohesion state, contact/cohesion_reach.hpp has_cohesion) touching, bridge (UInt8, 0/1).
// FieldData TimeValue.
void write_contacts_vtu(const std::filesystem::path& file, std::span<const ContactEntry> contacts, double time,
                        VtkFormat format, bool bodies = false, bool cohesion = false);

// Columns: time,first,second,element,px,py,pz,nx,ny,nz,overlap,fnx,fny,fnz,ftx,fty,ftz,sliding
// (s, -, -, -, m, -, m, N, N, -), with `bodies` first_body,second_body (-, -) after them, and
// with `cohesion` touching,bridge (0/1) after those: a scene of spheres without cohesion keeps its
// columns.
void write_contacts_csv(const std::filesystem::path& file, std::span<const ContactEntry> contacts, double time,
                        bool bodies = false, bool cohesion = false);

}  // namespace mpdem
