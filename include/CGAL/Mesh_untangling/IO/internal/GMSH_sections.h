// Copyright (c) 2026 Mesh_untangling contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sections of a Gmsh .msh file (MSH 2.2 and 4.1, text or binary), read
// one at a time into what the mesh needs.
#ifndef CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_SECTIONS_H
#define CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_SECTIONS_H

#include <CGAL/Mesh_untangling/IO/Mesh_file.h>
#include <CGAL/Mesh_untangling/IO/Read_error.h>
#include <CGAL/Mesh_untangling/IO/internal/GMSH_stream.h>
#include <CGAL/Mesh_untangling/IO/internal/mesh_file_checks.h>
#include <CGAL/Mesh_untangling/IO/internal/solid_cell_kinds.h>
#include <CGAL/Mesh_untangling/IO/internal/token_conversion.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <map>
#include <set>
#include <string>
#include <string_view>
#include <unordered_map>
#include <utility>
#include <vector>

namespace CGAL {
namespace Mesh_untangling {
namespace IO {
namespace internal {

// The elements a mesh can be made of (solid cells of any kind mix); points
// and lines are its corners and edges, the other types are refused.
enum GMSH_kind { GMSH_TRIANGLES, GMSH_QUADRANGLES, GMSH_SOLIDS, GMSH_LOWER_DIMENSION };

struct GMSH_type
{
  int nodes = 0;
  int dimension = 0;
  GMSH_kind kind = GMSH_LOWER_DIMENSION;
  const char* name = nullptr;   // nullptr: a type this reader refuses
};

// Gmsh's linear hexahedron numbers its nodes as VTK's (and MEDIT's) does: 0 1
// 2 3 the bottom face, counter-clockwise seen from above, then 4 5 6 7 above
// them (Gmsh's reference manual, "Node ordering"; PETSc's Gmsh reader maps
// them to the same corners), so hexahedra are read and written as they are.
// test_gmsh checks it on hexahedra that Gmsh made: all positively oriented.
// Its prism and pyramid are Mesh_file's too (the same manual's figures).
inline GMSH_type GMSH_type_of(long long type)
{
  switch(type) {
    case 15: return {1, 0, GMSH_LOWER_DIMENSION, "point"};
    case 1: return {2, 1, GMSH_LOWER_DIMENSION, "line"};
    case 2: return {3, 2, GMSH_TRIANGLES, "triangle"};
    case 3: return {4, 2, GMSH_QUADRANGLES, "quadrangle"};
    default: break;
  }
  const Solid_cell_kind* kind =
    type < 0 || type > 255 ? nullptr : find_solid_cell_kind(&Solid_cell_kind::GMSH_type, static_cast<int>(type));
  if(kind == nullptr)
    return {};
  return {kind->size, 3, GMSH_SOLIDS, kind->name};
}

// Why an element of `type` is refused (the types GMSH_type_of() does not know).
inline std::string GMSH_refusal(long long type)
{
  const std::string only = " (only linear triangles, quadrangles, tetrahedra, pyramids, prisms and hexahedra, "
                           "and points and lines, read as corners and edges)";
  static const char* const second_order[] = {
    "3-node second order line", "6-node second order triangle", "9-node second order quadrangle",
    "10-node second order tetrahedron", "27-node second order hexahedron", "18-node second order prism",
    "14-node second order pyramid", nullptr, "8-node second order quadrangle",
    "20-node second order hexahedron", "15-node second order prism", "13-node second order pyramid"};
  if(type >= 8 && type <= 19 && second_order[type - 8] != nullptr)
    return "is a " + std::string(second_order[type - 8]) + " (type " + std::to_string(type)
           + "): higher-order elements are not supported" + only;
  return "has element type " + std::to_string(type) + ", which is not supported" + only;
}

struct GMSH_elements
{
  std::vector<std::array<std::size_t, 8>> ids;   // 0-based vertex ids
  std::vector<unsigned char> sizes;              // nodes per element
  std::vector<std::size_t> lines;                // empty in a binary file
  std::size_t first_tag = 0;
  GMSH_place first_place;
};

// An entity or a physical group: its dimension and its tag.
typedef std::pair<long long, long long> GMSH_key;

struct GMSH_content
{
  int version = 0;                                   // 2 (MSH 2.2) or 4 (MSH 4.1); 0 before $MeshFormat
  GMSH_place nodes_place, elements_place;            // of the section names; line 0: no such section
  bool has_nodes = false, has_elements = false;
  std::vector<std::array<double, 3>> nodes;
  std::unordered_map<std::size_t, std::size_t> node_ids;   // node tag -> 0-based id
  std::array<GMSH_elements, 3> elements;             // by GMSH_kind
  bool has_fixed_group = false;
  std::set<GMSH_key> fixed_groups;                   // the physical groups named "fixed"
  std::map<GMSH_key, std::vector<long long>> entity_groups;   // MSH 4.1: an entity's physical tags
  std::vector<std::size_t> fixed;                    // ids, in any order, repeated
  std::vector<std::array<std::size_t, 2>> edges;     // the lines, as Mesh_file's
  std::vector<std::size_t> edge_lines;               // empty in a binary file
  std::vector<std::size_t> corners;                  // the points not in the group `fixed`, in any order, repeated
};

inline std::string GMSH_element_name(std::size_t tag) { return "element " + std::to_string(tag); }

// The line after a section must close it.
inline void expect_GMSH_end(GMSH_stream& stream, const std::string& end)
{
  std::string_view text;
  GMSH_place at;
  if(!stream.next_line(text, at))
    stream.fail_truncated("no " + end);
  if(text != end)
    stream.fail(at, "expected " + end + ", found " + quote_token(text));
}

inline void read_GMSH_format(GMSH_stream& stream, GMSH_content& content)
{
  std::string_view version;
  GMSH_place at;
  if(!stream.next_word(version, at))
    stream.fail_truncated("expected the version after $MeshFormat");
  if(version == "2.2")
    content.version = 2;
  else if(version == "4.1")
    content.version = 4;
  else
    stream.fail(at, "unsupported MSH version " + quote_token(version) + " (supported: 2.2 and 4.1)");
  const std::size_t file_type = stream.text_size([] { return std::string("file-type of $MeshFormat"); });
  const GMSH_place data_size_place = stream.last_place();
  const std::size_t data_size = stream.text_size([] { return std::string("data-size of $MeshFormat"); });
  if(file_type > 1)
    stream.fail(at, "file-type is " + std::to_string(file_type) + "; expected 0 (ASCII) or 1 (binary)");
  if(file_type == 1) {
    if(data_size != 8)
      stream.fail(data_size_place, "data-size is " + std::to_string(data_size)
                                       + "; only binary files with 8-byte size_t (data-size 8) are supported");
    stream.begin_binary_data("$MeshFormat");
    stream.set_binary(false);
    const long long one = stream.integer([] { return std::string("endianness check (the int 1)"); }, false);
    if(one == 0x01000000)
      stream.set_binary(true);
    else if(one != 1)
      stream.fail(stream.last_place(), "the endianness check is " + std::to_string(one) + "; expected 1");
  }
  expect_GMSH_end(stream, "$EndMeshFormat");
}

inline void read_GMSH_physical_names(GMSH_stream& stream, GMSH_content& content)
{
  if(content.has_elements)
    stream.fail(stream.place(), "$PhysicalNames after $Elements (Gmsh writes it before)");
  const std::size_t count = stream.text_size([] { return std::string("number of physical names"); });
  for(std::size_t i = 0; i < count; ++i) {
    const auto what = [i](const char* field) {
      return std::string(field) + " of physical name " + std::to_string(i + 1);
    };
    const long long dimension = static_cast<long long>(stream.text_size([&] { return what("dimension"); }));
    if(dimension > 3)
      stream.fail(stream.last_place(), what("dimension") + " is " + std::to_string(dimension) + "; expected 0 to 3");
    const long long tag = stream.text_integer([&] { return what("tag"); });
    const GMSH_place at = stream.last_place();
    const std::string_view name = stream.rest_of_line();
    if(name.size() < 2 || name.front() != '"' || name.back() != '"')
      stream.fail(at, what("name") + " is not in double quotes: " + quote_token(name));
    if(name.substr(1, name.size() - 2) == "fixed") {
      content.has_fixed_group = true;
      content.fixed_groups.insert(GMSH_key(dimension, tag));
    }
  }
  expect_GMSH_end(stream, "$EndPhysicalNames");
}

// MSH 4.1: the physical groups of every point, curve, surface and volume
// (their boxes and bounding entities are read only to be skipped).
inline void read_GMSH_entities(GMSH_stream& stream, GMSH_content& content)
{
  if(content.has_elements)
    stream.fail(stream.place(), "$Entities after $Elements (Gmsh writes it before)");
  if(stream.binary())
    stream.begin_binary_data("$Entities");
  static const char* const names[] = {"point", "curve", "surface", "volume"};
  std::array<std::size_t, 4> counts;
  for(int d = 0; d < 4; ++d)
    counts[d] = stream.size([d] { return "number of " + std::string(names[d]) + " entities"; });
  for(int d = 0; d < 4; ++d)
    for(std::size_t i = 0; i < counts[d]; ++i) {
      const auto what = [&](const char* field) {
        return std::string(field) + " of " + names[d] + " entity " + std::to_string(i + 1);
      };
      const long long tag = stream.integer([&] { return what("tag"); }, false);
      for(int c = 0; c < (d == 0 ? 3 : 6); ++c)
        stream.real([&] { return what("coordinate"); });
      std::vector<long long>& groups = content.entity_groups[GMSH_key(d, tag)];
      const std::size_t physical = stream.size([&] { return what("number of physical tags"); });
      groups.reserve(stream.sane_capacity(physical, 2));
      for(std::size_t p = 0; p < physical; ++p)
        groups.push_back(stream.integer([&] { return what("physical tag"); }, false));
      if(d == 0)
        continue;
      const std::size_t bounding = stream.size([&] { return what("number of bounding entities"); });
      for(std::size_t b = 0; b < bounding; ++b)
        stream.integer([&] { return what("bounding entity"); }, false);
    }
  expect_GMSH_end(stream, "$EndEntities");
}

inline void add_GMSH_node(GMSH_stream& stream, GMSH_content& content, std::size_t tag, const GMSH_place& at)
{
  const auto inserted = content.node_ids.emplace(tag, content.node_ids.size());
  if(!inserted.second)
    stream.fail(at, "node tag " + std::to_string(tag) + " appears twice in $Nodes");
}

inline std::array<double, 3> read_GMSH_point(GMSH_stream& stream, std::size_t tag)
{
  static const char* const axis[] = {"x", "y", "z"};
  std::array<double, 3> p;
  for(int c = 0; c < 3; ++c)
    p[c] = stream.real([&] { return std::string(axis[c]) + " coordinate of node " + std::to_string(tag); });
  return p;
}

inline void read_GMSH_nodes_2(GMSH_stream& stream, GMSH_content& content)
{
  const std::size_t count = stream.text_size([] { return std::string("number of nodes"); });
  if(stream.binary())
    stream.begin_binary_data("$Nodes");
  content.nodes.reserve(stream.sane_capacity(count, stream.binary() ? 28 : 8));
  for(std::size_t i = 0; i < count; ++i) {
    const std::size_t tag = static_cast<std::size_t>(
      stream.integer([i] { return "tag of node " + std::to_string(i + 1) + " of $Nodes"; }));
    add_GMSH_node(stream, content, tag, stream.last_place());
    content.nodes.push_back(read_GMSH_point(stream, tag));
  }
}

inline void read_GMSH_nodes_4(GMSH_stream& stream, GMSH_content& content)
{
  if(stream.binary())
    stream.begin_binary_data("$Nodes");
  const std::size_t blocks = stream.size([] { return std::string("number of node blocks"); });
  const GMSH_place count_place = stream.place();
  const std::size_t count = stream.size([] { return std::string("number of nodes"); });
  stream.size([] { return std::string("smallest node tag"); });
  stream.size([] { return std::string("largest node tag"); });
  content.nodes.reserve(stream.sane_capacity(count, stream.binary() ? 32 : 8));
  std::vector<std::pair<std::size_t, GMSH_place>> tags;
  std::size_t total = 0;
  for(std::size_t b = 0; b < blocks; ++b) {
    const auto what = [b](const char* field) { return std::string(field) + " of node block " + std::to_string(b + 1); };
    const long long dimension = stream.integer([&] { return what("entity dimension"); });
    if(dimension > 3)
      stream.fail(stream.last_place(),
                  what("entity dimension") + " is " + std::to_string(dimension) + "; expected 0 to 3");
    stream.integer([&] { return what("entity tag"); }, false);
    const long long parametric = stream.integer([&] { return what("parametric flag"); });
    if(parametric > 1)
      stream.fail(stream.last_place(),
                  what("parametric flag") + " is " + std::to_string(parametric) + "; expected 0 or 1");
    const std::size_t n = stream.size([&] { return what("number of nodes"); });
    tags.clear();
    tags.reserve(stream.sane_capacity(n, 8));
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t tag = stream.size([&] { return "tag " + std::to_string(i + 1) + what(""); });
      tags.emplace_back(tag, stream.last_place());
    }
    for(const auto& tag : tags) {
      add_GMSH_node(stream, content, tag.first, tag.second);
      content.nodes.push_back(read_GMSH_point(stream, tag.first));
      // (parametric coordinates: one per dimension of the entity)
      for(long long u = 0; u < (parametric == 1 ? dimension : 0); ++u)
        stream.real([&] { return "parametric coordinate of node " + std::to_string(tag.first); });
    }
    total += n;
  }
  if(total != count)
    stream.fail(count_place, "$Nodes announces " + std::to_string(count) + " nodes but its blocks hold "
                                 + std::to_string(total));
}

// Lines are edges.  Points are corners, but those of the group `fixed`: as
// write_GMSH() writes the fixed vertices, they say only that.
inline void add_GMSH_edge_or_corner(const GMSH_stream& stream, GMSH_content& content, const GMSH_type& type,
                                    const std::array<std::size_t, 8>& ids, const GMSH_place& at, bool fixed)
{
  if(type.nodes == 2) {
    content.edges.push_back({ids[0], ids[1]});
    if(!stream.binary())
      content.edge_lines.push_back(at.line);
  } else if(!fixed) {
    content.corners.push_back(ids[0]);
  }
}

// Reads the node tags of one element (`read_tag` reads one) and files the
// element: under its kind when it may be of the mesh, and its vertices
// as fixed when it is in the group `fixed`.
template <class Read_tag>
void read_GMSH_element(GMSH_stream& stream, GMSH_content& content, const GMSH_type& type, std::size_t tag,
                       const GMSH_place& at, bool fixed, const Read_tag& read_tag)
{
  std::array<std::size_t, 8> ids = {0, 0, 0, 0, 0, 0, 0, 0};
  std::array<std::size_t, 8> tags = ids;
  for(int c = 0; c < type.nodes; ++c) {
    tags[c] = read_tag([&] { return "node " + std::to_string(c + 1) + " of " + GMSH_element_name(tag); });
    const auto found = content.node_ids.find(tags[c]);
    if(found == content.node_ids.end())
      stream.fail(stream.last_place(), GMSH_element_name(tag) + " (" + type.name + ") refers to node "
                                           + std::to_string(tags[c])
                                           + ", which $Nodes does not list");
    ids[c] = found->second;
    for(int e = 0; e < c; ++e)
      if(tags[e] == tags[c])
        stream.fail(stream.last_place(), GMSH_element_name(tag) + " (" + type.name + ") has node "
                                             + std::to_string(tags[c]) + " twice");
  }
  if(fixed)
    content.fixed.insert(content.fixed.end(), ids.begin(), ids.begin() + type.nodes);
  if(type.kind == GMSH_LOWER_DIMENSION)
    return add_GMSH_edge_or_corner(stream, content, type, ids, at, fixed);
  GMSH_elements& elements = content.elements[type.kind];
  if(elements.ids.empty()) {
    elements.first_tag = tag;
    elements.first_place = at;
  }
  elements.ids.push_back(ids);
  elements.sizes.push_back(static_cast<unsigned char>(type.nodes));
  if(!stream.binary())
    elements.lines.push_back(at.line);
}

inline GMSH_type known_GMSH_type(GMSH_stream& stream, long long type, std::size_t tag, const GMSH_place& at)
{
  const GMSH_type known = GMSH_type_of(type);
  if(known.name == nullptr)
    stream.fail(at, GMSH_element_name(tag) + " " + GMSH_refusal(type));
  return known;
}

inline void read_GMSH_elements_2(GMSH_stream& stream, GMSH_content& content)
{
  const std::size_t count = stream.text_size([] { return std::string("number of elements"); });
  // (MSH 2.2: the first tag of an element is its physical group)
  const auto in_fixed_group = [&](const GMSH_type& type, const std::vector<long long>& tags) {
    return !tags.empty() && content.fixed_groups.count(GMSH_key(type.dimension, tags[0])) != 0;
  };
  const auto read_int = [&](const auto& describe) { return static_cast<std::size_t>(stream.integer(describe)); };
  std::vector<long long> tags;
  if(!stream.binary()) {
    for(std::size_t i = 0; i < count; ++i) {
      const auto what = [i](const char* field) {
        return std::string(field) + " of element " + std::to_string(i + 1) + " of $Elements";
      };
      const std::size_t tag = stream.text_size([&] { return what("tag"); });
      const GMSH_place at = stream.last_place();
      const GMSH_type type = known_GMSH_type(stream, stream.text_integer([&] { return what("type"); }), tag, at);
      const std::size_t number_of_tags = stream.text_size([&] { return what("number of tags"); });
      tags.clear();
      for(std::size_t t = 0; t < number_of_tags; ++t)
        tags.push_back(stream.text_integer([&] { return what("tag"); }));
      read_GMSH_element(stream, content, type, tag, at, in_fixed_group(type, tags), read_int);
    }
    return;
  }
  // Binary: blocks of elements of one type with as many tags each.
  stream.begin_binary_data("$Elements");
  for(std::size_t done = 0; done < count;) {
    const auto what = [done](const char* field) {
      return std::string(field) + " of the element block after " + std::to_string(done) + " elements";
    };
    const long long type_number = stream.integer([&] { return what("type"); });
    const std::size_t in_block = read_int([&] { return what("number of elements"); });
    const std::size_t number_of_tags = read_int([&] { return what("number of tags"); });
    if(in_block > count - done)
      stream.fail(stream.last_place(), "the element blocks hold more than the " + std::to_string(count)
                                           + " elements $Elements announces");
    if(in_block == 0)
      stream.fail(stream.last_place(), what("number of elements") + " is 0");
    for(std::size_t i = 0; i < in_block; ++i) {
      const std::size_t tag = read_int([&] { return "tag of element " + std::to_string(done + i + 1); });
      const GMSH_place at = stream.last_place();
      const GMSH_type type = known_GMSH_type(stream, type_number, tag, at);
      tags.clear();
      for(std::size_t t = 0; t < number_of_tags; ++t)
        tags.push_back(stream.integer([&] { return "tag of " + GMSH_element_name(tag); }, false));
      read_GMSH_element(stream, content, type, tag, at, in_fixed_group(type, tags), read_int);
    }
    done += in_block;
  }
}

inline bool GMSH_entity_is_fixed(const GMSH_content& content, long long dimension, long long entity)
{
  const auto found = content.entity_groups.find(GMSH_key(dimension, entity));
  if(found == content.entity_groups.end())
    return false;
  for(long long group : found->second)
    if(content.fixed_groups.count(GMSH_key(dimension, group)) != 0)
      return true;
  return false;
}

inline void read_GMSH_elements_4(GMSH_stream& stream, GMSH_content& content)
{
  if(stream.binary())
    stream.begin_binary_data("$Elements");
  const std::size_t blocks = stream.size([] { return std::string("number of element blocks"); });
  const GMSH_place count_place = stream.place();
  const std::size_t count = stream.size([] { return std::string("number of elements"); });
  stream.size([] { return std::string("smallest element tag"); });
  stream.size([] { return std::string("largest element tag"); });
  const auto read_size = [&](const auto& describe) { return stream.size(describe); };
  std::size_t total = 0;
  for(std::size_t b = 0; b < blocks; ++b) {
    const auto what = [b](const char* field) {
      return std::string(field) + " of element block " + std::to_string(b + 1);
    };
    const long long dimension = stream.integer([&] { return what("entity dimension"); });
    const long long entity = stream.integer([&] { return what("entity tag"); }, false);
    const long long type_number = stream.integer([&] { return what("element type"); });
    const std::size_t n = stream.size([&] { return what("number of elements"); });
    const bool fixed = GMSH_entity_is_fixed(content, dimension, entity);
    for(std::size_t i = 0; i < n; ++i) {
      const std::size_t tag = stream.size([&] { return "tag " + std::to_string(i + 1) + what(""); });
      const GMSH_place at = stream.last_place();
      const GMSH_type type = known_GMSH_type(stream, type_number, tag, at);
      read_GMSH_element(stream, content, type, tag, at, fixed, read_size);
    }
    total += n;
  }
  if(total != count)
    stream.fail(count_place, "$Elements announces " + std::to_string(count) + " elements but its blocks hold "
                                 + std::to_string(total));
}

inline void read_GMSH_section(GMSH_stream& stream, std::string_view name, const GMSH_place& at, GMSH_content& content)
{
  if(name == "$MeshFormat")
    stream.fail(at, "second $MeshFormat section");
  if(name == "$PhysicalNames")
    return read_GMSH_physical_names(stream, content);
  if(name == "$Entities" && content.version == 4)
    return read_GMSH_entities(stream, content);
  if(name == "$Nodes" || name == "$Elements") {
    const bool nodes = name == "$Nodes";
    bool& seen = nodes ? content.has_nodes : content.has_elements;
    GMSH_place& first = nodes ? content.nodes_place : content.elements_place;
    if(seen) {
      const std::string where = stream.binary() ? "byte " + std::to_string(first.offset)
                                                : "line " + std::to_string(first.line);
      stream.fail(at, "second " + std::string(name) + " section (the first is at " + where + ")");
    }
    if(!nodes && !content.has_nodes)
      stream.fail(at, "$Elements before $Nodes (Gmsh writes the nodes first)");
    seen = true;
    first = at;
    if(nodes)
      content.version == 2 ? read_GMSH_nodes_2(stream, content) : read_GMSH_nodes_4(stream, content);
    else
      content.version == 2 ? read_GMSH_elements_2(stream, content) : read_GMSH_elements_4(stream, content);
    return expect_GMSH_end(stream, nodes ? "$EndNodes" : "$EndElements");
  }
  if(name.substr(0, 4) == "$End")
    stream.fail(at, quote_token(name) + " closes no section");
  // Any other section ($Comments, $PartitionedEntities, $Periodic, $NodeData, ...) is not needed.
  const std::string end = "$End" + std::string(name.substr(1));
  if(!stream.skip_to_line(end))
    stream.fail(at, "truncated: the " + std::string(name) + " section has no " + end);
}

inline GMSH_content read_GMSH_content(GMSH_stream& stream)
{
  GMSH_content content;
  std::string_view text;
  GMSH_place at;
  if(!stream.next_line(text, at))
    stream.fail_truncated("the file is empty; a .msh file starts with $MeshFormat");
  if(text != "$MeshFormat")
    stream.fail(at, "not a Gmsh file: expected $MeshFormat, found " + quote_token(text));
  read_GMSH_format(stream, content);
  while(stream.next_line(text, at)) {
    if(text[0] != '$')
      stream.fail(at, "expected a section name ($...), found " + quote_token(text));
    read_GMSH_section(stream, text, at, content);
  }
  if(!content.has_nodes)
    stream.fail_truncated("no $Nodes section");
  return content;
}

// The elements of the highest dimension are the mesh: solid cells, of any
// kinds, stored by the rule of Mesh_file, over triangles or quadrangles (a
// volume mesh lists its boundary faces too).  Faces of both kinds are mixed
// cells: rejected.
inline void select_GMSH_elements(const GMSH_stream& stream, GMSH_content& content, Mesh_file& mesh)
{
  GMSH_elements& solids = content.elements[GMSH_SOLIDS];
  GMSH_elements& triangles = content.elements[GMSH_TRIANGLES];
  GMSH_elements& quadrangles = content.elements[GMSH_QUADRANGLES];
  if(!solids.ids.empty()) {
    for(std::size_t i = 0; i < solids.ids.size(); ++i)
      add_solid_cell(mesh, solids.ids[i], solids.sizes[i], solids.lines.empty() ? 0 : solids.lines[i]);
  } else if(!triangles.ids.empty() && !quadrangles.ids.empty()) {
    const bool quadrangles_later = quadrangles.first_place.offset > triangles.first_place.offset;
    const GMSH_elements& later = quadrangles_later ? quadrangles : triangles;
    const GMSH_elements& earlier = quadrangles_later ? triangles : quadrangles;
    stream.fail(later.first_place, "mixed element types: " + GMSH_element_name(later.first_tag) + " is a "
                                       + (quadrangles_later ? "quadrangle" : "triangle") + " but "
                                       + GMSH_element_name(earlier.first_tag) + " is a "
                                       + (quadrangles_later ? "triangle" : "quadrangle")
                                       + "; a mesh holds one element type");
  } else if(!quadrangles.ids.empty()) {
    mesh.cell_size = 4;
    mesh.cells = std::move(quadrangles.ids);
    mesh.cell_lines = std::move(quadrangles.lines);
  } else if(!triangles.ids.empty()) {
    mesh.simplex_size = 3;
    mesh.simplices.reserve(triangles.ids.size());
    for(const std::array<std::size_t, 8>& s : triangles.ids)
      mesh.simplices.push_back({s[0], s[1], s[2], 0});
    mesh.simplex_lines = std::move(triangles.lines);
  }
  mesh.has_fixed = content.has_fixed_group;
  sort_without_duplicates(content.fixed);
  mesh.fixed = std::move(content.fixed);
  mesh.edges = std::move(content.edges);
  mesh.edge_lines = std::move(content.edge_lines);
  sort_without_duplicates(content.corners);
  mesh.corners = std::move(content.corners);
}

} // namespace internal
} // namespace IO
} // namespace Mesh_untangling
} // namespace CGAL

#endif // CGAL_MESH_UNTANGLING_IO_INTERNAL_GMSH_SECTIONS_H
