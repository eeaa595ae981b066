# The pass list and the permutation axes, read from shaders_common/ffx_dof_permutations.json: the one
# place they are written. CMake code asks ffx_dof_pass_names(); C++ includes the header that
# ffx_dof_generate_pass_list() writes (ffx_dof_pass_list.h: enum Pass, the typed axes, the flag mapping).
include_guard(GLOBAL)

function(_ffx_dof_read_permutations json_var)
  get_property(json_file GLOBAL PROPERTY FFX_DOF_PERMUTATIONS_JSON)
  if(NOT json_file)
    message(FATAL_ERROR "FFX_DOF_PERMUTATIONS_JSON is not set (shaders_common/CMakeLists.txt sets it)")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${json_file}")
  file(READ "${json_file}" json)
  set(${json_var} "${json}" PARENT_SCOPE)
endfunction()

# The pass names in pipeline order (downsample_depth;...;composite).
function(ffx_dof_pass_names out_var)
  _ffx_dof_read_permutations(json)
  string(JSON pass_count LENGTH "${json}" passes)
  set(names "")
  math(EXPR last "${pass_count} - 1")
  foreach(i RANGE ${last})
    string(JSON name GET "${json}" passes ${i} name)
    list(APPEND names ${name})
  endforeach()
  set(${out_var} ${names} PARENT_SCOPE)
endfunction()

# The passes whose FFX_HALF=1 permutations carry colour in 16-bit floats ("float16Color").
function(ffx_dof_float16_color_passes out_var)
  _ffx_dof_read_permutations(json)
  ffx_dof_pass_names(names)
  set(result "")
  set(i 0)
  foreach(name IN LISTS names)
    string(JSON flag ERROR_VARIABLE missing GET "${json}" passes ${i} float16Color)
    if(NOT missing AND flag)
      list(APPEND result ${name})
    endif()
    math(EXPR i "${i} + 1")
  endforeach()
  set(${out_var} ${result} PARENT_SCOPE)
endfunction()

# snake_case / MACRO_CASE words -> camelCase (upper_first: PascalCase).
function(_ffx_dof_camel_case text upper_first out_var)
  string(TOLOWER "${text}" lower)
  string(REPLACE "_" ";" words "${lower}")
  set(result "")
  set(first ON)
  foreach(word IN LISTS words)
    if(first AND NOT upper_first)
      string(APPEND result "${word}")
    else()
      string(SUBSTRING "${word}" 0 1 head)
      string(SUBSTRING "${word}" 1 -1 tail)
      string(TOUPPER "${head}" head)
      string(APPEND result "${head}${tail}")
    endif()
    set(first OFF)
  endforeach()
  set(${out_var} "${result}" PARENT_SCOPE)
endfunction()

# The axis's field name: the macro without FFX_DOF_OPTION_ / FFX_, in camelCase (FFX_HALF -> half).
function(_ffx_dof_axis_field macro out_var)
  string(REGEX REPLACE "^FFX_DOF_OPTION_|^FFX_" "" stem "${macro}")
  _ffx_dof_camel_case("${stem}" OFF field)
  set(${out_var} "${field}" PARENT_SCOPE)
endfunction()

# Writes <out_dir>/ffx_dof_pass_list.h.
function(ffx_dof_generate_pass_list out_dir)
  _ffx_dof_read_permutations(json)
  get_property(json_file GLOBAL PROPERTY FFX_DOF_PERMUTATIONS_JSON)

  # The axes, in the order of the "axes" object.
  string(JSON axis_count LENGTH "${json}" axes)
  set(axis_enum "")
  set(axis_macros "")
  set(axis_fields "")
  set(axis_value_cases "")
  set(flag_assignments "")
  set(all_macros "")
  set(dispatch_macros "")
  set(axis_dispatch_values "")
  set(axis_tile_lists "")
  set(tile_list_macros "")
  set(max_variants 1)
  math(EXPR last_axis "${axis_count} - 1")
  foreach(a RANGE ${last_axis})
    string(JSON macro MEMBER "${json}" axes ${a})
    string(JSON chosen_by GET "${json}" axes ${macro} chosenBy)
    list(APPEND all_macros ${macro})
    # perDispatch: the values a context with the flag takes per dispatch, one pipeline each.
    string(JSON dispatch_count ERROR_VARIABLE no_dispatch LENGTH "${json}" axes ${macro} perDispatch)
    if(chosen_by STREQUAL "tileLists")
      # "firstList": the macro of ffx_dof_resources.h that numbers the axis's first list (value v: list first + v).
      string(JSON first_list ERROR_VARIABLE no_first_list GET "${json}" axes ${macro} firstList)
      if(no_first_list OR NOT first_list MATCHES "^FFX_DOF_[A-Z0-9_]+$")
        message(FATAL_ERROR "${json_file}: axis ${macro}: an axis chosen by tileLists needs \"firstList\", a macro of ffx_dof_resources.h")
      endif()
      string(APPEND axis_tile_lists "true, ")
      list(APPEND tile_list_macros ${macro})
      set(_ffx_dof_first_list_${macro} ${first_list})
      set(_ffx_dof_tile_list_pass_${macro} "")
    else()
      string(APPEND axis_tile_lists "false, ")
    endif()
    if(no_dispatch)
      string(APPEND axis_dispatch_values "{0, {}}, ")
      set(_ffx_dof_dispatch_values_${macro} "")
    else()
      if(NOT chosen_by MATCHES "^FFX_DOF_[A-Z0-9_]+$" OR dispatch_count LESS 2)
        message(FATAL_ERROR "${json_file}: axis ${macro}: perDispatch needs a context flag in chosenBy and at least two values")
      endif()
      set(values "")
      math(EXPR last_value "${dispatch_count} - 1")
      foreach(v RANGE ${last_value})
        string(JSON value GET "${json}" axes ${macro} perDispatch ${v})
        list(APPEND values ${value})
      endforeach()
      set(_ffx_dof_dispatch_values_${macro} "${values}")
      list(JOIN values ", " joined)
      string(APPEND axis_dispatch_values "{${dispatch_count}, {${joined}}}, ")
      list(APPEND dispatch_macros ${macro})
      if(dispatch_count GREATER max_variants)
        set(max_variants ${dispatch_count})
      endif()
    endif()
    _ffx_dof_axis_field(${macro} field)
    string(SUBSTRING "${field}" 0 1 head)
    string(SUBSTRING "${field}" 1 -1 tail)
    string(TOUPPER "${head}" head)
    set(enumerator "${head}${tail}")
    string(APPEND axis_enum "${enumerator}, ")
    string(APPEND axis_macros "\"${macro}\", ")
    if(chosen_by STREQUAL "tileLists")
      if(NOT no_dispatch)
        message(FATAL_ERROR "${json_file}: axis ${macro}: an axis chosen by tileLists takes no perDispatch values")
      endif()
      string(APPEND axis_fields "    uint32_t ${field} = 0;  // ${macro}: every value, one pipeline per tile list (kAxisRunsPerTileList)\n")
    elseif(chosen_by STREQUAL "device")
      string(APPEND axis_fields "    uint32_t ${field} = 0;  // ${macro}: chosen by the backend's device\n")
    elseif(chosen_by MATCHES "^FFX_DOF_[A-Z0-9_]+$" AND NOT no_dispatch)
      string(APPEND axis_fields "    uint32_t ${field} = 0;  // ${macro}: 1 when the context has ${chosen_by} (then one of ${joined} per dispatch)\n")
      string(APPEND flag_assignments "    axes->${field} = (flags & ${chosen_by}) ? 1u : 0u;\n")
    elseif(chosen_by MATCHES "^FFX_DOF_[A-Z0-9_]+$")
      string(APPEND axis_fields "    uint32_t ${field} = 0;  // ${macro}: 1 when the context has ${chosen_by}\n")
      string(APPEND flag_assignments "    axes->${field} = (flags & ${chosen_by}) ? 1u : 0u;\n")
    else()
      message(FATAL_ERROR "${json_file}: axis ${macro}: chosenBy '${chosen_by}' is neither \"device\", \"tileLists\" nor a context flag")
    endif()
    string(APPEND axis_value_cases "        case Axis::${enumerator}: return axes.${field};\n")
  endforeach()

  # The passes and their axes.
  string(JSON pass_count LENGTH "${json}" passes)
  set(pass_enum "")
  set(pass_names "")
  set(pass_axis_rows "")
  set(pass_axis_counts "")
  set(pass_domains "")
  set(pass_float16 "")
  set(pass_extents "")
  math(EXPR last_pass "${pass_count} - 1")
  foreach(p RANGE ${last_pass})
    string(JSON name GET "${json}" passes ${p} name)
    _ffx_dof_camel_case("${name}" ON enumerator)
    string(APPEND pass_enum "${enumerator}, ")
    string(APPEND pass_names "\"${name}\", ")
    # Each pass's dispatch geometry is in ffx_dof_resources.h under the pass's name.
    string(TOUPPER "${name}" upper)
    string(APPEND pass_domains "FFX_DOF_${upper}_DOMAIN, ")
    string(APPEND pass_extents "FFX_DOF_${upper}_GROUP_EXTENT, ")
    string(JSON float16 ERROR_VARIABLE missing GET "${json}" passes ${p} float16Color)
    if(NOT missing AND float16)
      string(APPEND pass_float16 "true, ")
    else()
      string(APPEND pass_float16 "false, ")
    endif()
    string(JSON pass_axis_count LENGTH "${json}" passes ${p} axes)
    set(row "")
    set(pass_dispatch_axes 0)
    set(pass_list_axes 0)
    set(pass_dispatch_values 1)
    set(pass_list_values 1)
    if(pass_axis_count GREATER 0)
      math(EXPR last "${pass_axis_count} - 1")
      foreach(a RANGE ${last})
        string(JSON macro MEMBER "${json}" passes ${p} axes ${a})
        if(NOT macro IN_LIST all_macros)
          message(FATAL_ERROR "${json_file}: pass ${name} has the axis ${macro}, which \"axes\" does not list")
        endif()
        if(macro IN_LIST tile_list_macros)
          math(EXPR pass_list_axes "${pass_list_axes} + 1")
          string(JSON pass_values GET "${json}" passes ${p} axes ${macro})
          string(REGEX REPLACE "[][ ]" "" pass_values "${pass_values}")
          string(REPLACE "," ";" pass_values "${pass_values}")
          list(LENGTH pass_values list_count)
          set(pass_list_values ${list_count})
          # The values number the pass's lists: 0, 1, ... in order, and no other pass runs over them.
          set(expected 0)
          foreach(value IN LISTS pass_values)
            if(NOT value EQUAL expected)
              message(FATAL_ERROR "${json_file}: pass ${name}: the values of the tileLists axis ${macro} must be 0, 1, 2, ... in order")
            endif()
            math(EXPR expected "${expected} + 1")
          endforeach()
          if(NOT _ffx_dof_tile_list_pass_${macro} STREQUAL "")
            message(FATAL_ERROR "${json_file}: the tileLists axis ${macro} belongs to the passes ${_ffx_dof_tile_list_pass_${macro}} and ${name}; each pass needs lists of its own")
          endif()
          set(_ffx_dof_tile_list_pass_${macro} ${name})
          set(_ffx_dof_tile_list_count_${macro} ${list_count})
        endif()
        if(macro IN_LIST dispatch_macros)
          math(EXPR pass_dispatch_axes "${pass_dispatch_axes} + 1")
          list(LENGTH _ffx_dof_dispatch_values_${macro} pass_dispatch_values)
          string(JSON pass_values GET "${json}" passes ${p} axes ${macro})
          string(REGEX REPLACE "[][ ]" "" pass_values "${pass_values}")
          string(REPLACE "," ";" pass_values "${pass_values}")
          foreach(value IN LISTS _ffx_dof_dispatch_values_${macro} ITEMS 0)
            if(NOT value IN_LIST pass_values)
              message(FATAL_ERROR "${json_file}: pass ${name}: axis ${macro} lacks the value ${value}, which perDispatch or a context without the flag takes")
            endif()
          endforeach()
        endif()
        _ffx_dof_axis_field(${macro} field)
        string(SUBSTRING "${field}" 0 1 head)
        string(SUBSTRING "${field}" 1 -1 tail)
        string(TOUPPER "${head}" head)
        string(APPEND row "Axis::${head}${tail}, ")
      endforeach()
    endif()
    if(pass_dispatch_axes GREATER 1 OR pass_list_axes GREATER 1)
      message(FATAL_ERROR "${json_file}: pass ${name} has more than one perDispatch axis or more than one tileLists axis; a dispatch chooses its pipelines by one of each")
    endif()
    # A dispatch's group of pipelines, one per list, for each per-dispatch value.
    math(EXPR pass_variants "${pass_dispatch_values} * ${pass_list_values}")
    if(pass_variants GREATER max_variants)
      set(max_variants ${pass_variants})
    endif()
    string(APPEND pass_axis_rows "    {${row}},  // ${name}\n")
    string(APPEND pass_axis_counts "${pass_axis_count}, ")
  endforeach()

  # Per axis: its first tile list and how many it runs over (0, 0 for the others).
  set(axis_tile_list_ranges "")
  foreach(macro IN LISTS all_macros)
    if(macro IN_LIST tile_list_macros)
      if(NOT DEFINED _ffx_dof_tile_list_count_${macro})
        message(FATAL_ERROR "${json_file}: no pass has the tileLists axis ${macro}")
      endif()
      string(APPEND axis_tile_list_ranges "{${_ffx_dof_first_list_${macro}}, ${_ffx_dof_tile_list_count_${macro}}}, ")
    else()
      string(APPEND axis_tile_list_ranges "{0, 0}, ")
    endif()
  endforeach()

  set(content "// Generated by cmake/FfxDofPassList.cmake from shaders_common/ffx_dof_permutations.json; do not edit.
// The passes in pipeline order and their permutation axes, typed.
#pragma once

#include \"ffx_dof.h\"
#include \"ffx_dof_resources.h\"

#include <cstdint>

namespace ffxdof {

// Pipeline order. The names are the shader header names (shaders_common/ffx_dof_<name>.h).
enum class Pass : uint32_t { ${pass_enum}};
constexpr uint32_t kPassCount = ${pass_count};
constexpr const char* kPassNames[kPassCount] = {${pass_names}};
// What a pass's workgroups cover (FFX_DOF_DOMAIN_*) and how much of it one workgroup covers.
constexpr uint32_t kPassDomain[kPassCount] = {${pass_domains}};
constexpr uint32_t kPassGroupExtent[kPassCount] = {${pass_extents}};
// Whether the pass's FFX_HALF=1 permutations carry colour in 16-bit floats.
constexpr bool kPassFloat16Color[kPassCount] = {${pass_float16}};

// Every permutation axis of any pass.
enum class Axis : uint32_t { ${axis_enum}};
constexpr uint32_t kAxisCount = ${axis_count};
constexpr const char* kAxisMacros[kAxisCount] = {${axis_macros}};

// One value per axis: a pass uses the values of its own axes and ignores the others.
struct PermutationAxes {
${axis_fields}};

inline uint32_t axisValue(const PermutationAxes& axes, Axis axis) {
    switch (axis) {
${axis_value_cases}    }
    return 0;
}

// The axes chosen by context flags (each has the flag's name and sense).
inline void setAxesFromContextFlags(uint32_t flags, PermutationAxes* axes) {
${flag_assignments}}

// The most pipelines of one pass: its per-dispatch values times its tile lists.
constexpr uint32_t kMaxPassVariants = ${max_variants};
// The values an axis takes per dispatch where its context flag is set (perDispatch; count 0: the
// context's value for every dispatch). A pass has at most one such axis.
struct AxisDispatchValues {
    uint32_t count;
    uint32_t values[kMaxPassVariants];
};
constexpr AxisDispatchValues kAxisDispatchValues[kAxisCount] = {${axis_dispatch_values}};
// Axes chosen by \"tileLists\": every dispatch runs the pass once per value of the axis the pass lists,
// each time with that value's pipeline and indirectly over the value's tile list (TILE_LIST_ARGS,
// TILE_LISTS in ffx_dof_resources.h): value v is list first + v of the axis's kAxisTileLists.
constexpr bool kAxisRunsPerTileList[kAxisCount] = {${axis_tile_lists}};
struct AxisTileLists {
    uint32_t first;  // the list of value 0 (the macro \"firstList\" names)
    uint32_t count;  // the values the pass lists, 0 for the other axes
};
constexpr AxisTileLists kAxisTileLists[kAxisCount] = {${axis_tile_list_ranges}};
constexpr bool tileListsFit() {
    for (const AxisTileLists& lists : kAxisTileLists) {
        if (lists.first + lists.count > FFX_DOF_TILE_LIST_COUNT) return false;
    }
    return true;
}
static_assert(tileListsFit(), \"a tileLists axis runs past FFX_DOF_TILE_LIST_COUNT\");

// The axes of each pass, in the order of its shader table.
constexpr uint32_t kPassAxisCount[kPassCount] = {${pass_axis_counts}};
constexpr Axis kPassAxes[kPassCount][kAxisCount] = {
${pass_axis_rows}};

}  // namespace ffxdof
")
  file(CONFIGURE OUTPUT "${out_dir}/ffx_dof_pass_list.h" CONTENT "${content}" @ONLY)
endfunction()
