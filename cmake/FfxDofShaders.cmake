# ffx_dof_add_shader_library: every permutation of every pass, compiled by ffx-dof-shaderc at build
# time into a static library of embedded SPIR-V tables.
#
#   ffx_dof_add_shader_library(<target> LANGUAGE glsl|hlsl|dxil
#       [DXC <program or target>]          LANGUAGE dxil only: the dxc to run (default FFX_DOF_DXC)
#       [NAMESPACE <c++ namespace>]        default ffxdof::shaders::<language>
#       [PASSES <pass>...]                 default: every pass of the permutations JSON
#       [PERMUTATIONS_JSON <file>]         default: global property FFX_DOF_PERMUTATIONS_JSON
#       [SOURCE_DIR <dir>]                 default: shaders_common/entry (ffx_dof_<pass>.<language>;
#                                          .hlsl for dxil)
#       [INCLUDE_DIRS <dir>...]            default: shaders_common
#       [DEFINES NAME=VALUE...]            plain defines in every permutation
#       [HLSL_SHIFTS t=N u=N s=N b=N]      HLSL register class -> binding shifts (SPIR-V only;
#                                          ignored for dxil, which binds the registers)
#       [NO_INSTALL])
#
# <target> links ffx_dof_shader_table and has <target>.h on its include path, declaring in the
# namespace: `extern const ffxdof::shaders::PassTable pass_<pass>;` per pass, `kPassTables`,
# `kPassTableCount` and `const ffxdof::shaders::PassTable* findPassTable(const char* pass)`
# (nullptr for an unknown pass). Only headers a pass really includes trigger its recompilation
# (the tool writes a depfile).
#
# DXIL for the D3D12 backend (end of this file): on Windows, or wherever FFX_DOF_DXC is set, dxc
# is looked up; when found and the D3D12 backend is built, the target ffx_dof_shaders_dxil is made
# (LANGUAGE dxil) and FFX_DOF_HAVE_DXIL is ON. Elsewhere there is no DXIL, and the D3D12 backend
# reports FFX_DOF_ERROR_UNSUPPORTED at context creation. See docs/permutations.md.
set(FFX_DOF_HAVE_DXIL OFF CACHE INTERNAL "Whether DXIL shader tables are built")

function(ffx_dof_add_shader_library target)
  cmake_parse_arguments(PARSE_ARGV 1 arg "NO_INSTALL" "LANGUAGE;DXC;NAMESPACE;PERMUTATIONS_JSON;SOURCE_DIR"
                        "PASSES;INCLUDE_DIRS;DEFINES;HLSL_SHIFTS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): unknown arguments: ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_LANGUAGE MATCHES "^(glsl|hlsl|dxil)$")
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): LANGUAGE must be glsl, hlsl or dxil, got '${arg_LANGUAGE}'")
  endif()
  # DXIL is compiled from the HLSL sources by dxc; the tool needs its path and reads no shifts.
  set(source_language ${arg_LANGUAGE})
  set(dxc_args "")
  set(dxc_depends "")
  if(arg_LANGUAGE STREQUAL "dxil")
    set(source_language hlsl)
    if(NOT arg_DXC)
      set(arg_DXC "${FFX_DOF_DXC}")
    endif()
    if(TARGET "${arg_DXC}")
      set(dxc_args --dxc "$<TARGET_FILE:${arg_DXC}>")
      set(dxc_depends "${arg_DXC}")
    elseif(arg_DXC AND EXISTS "${arg_DXC}")
      set(dxc_args --dxc "${arg_DXC}")
      set(dxc_depends "${arg_DXC}")
    else()
      message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): LANGUAGE dxil needs DXC (a dxc program or target); "
                          "'${arg_DXC}' is neither (set FFX_DOF_DXC)")
    endif()
    set(arg_HLSL_SHIFTS "")
  elseif(arg_DXC)
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): DXC is for LANGUAGE dxil only")
  endif()
  # FFX_DOF_SHADERC: a prebuilt ffx-dof-shaderc that compiles the permutations instead of this build's
  # own. The sanitizer build (tools/test.sh) takes the Release build's: its own, a Debug build under
  # ASan, took five times as long for the same blobs (the blur's GLSL permutations 105 s against 22 s).
  if(FFX_DOF_SHADERC)
    if(NOT EXISTS "${FFX_DOF_SHADERC}")
      message(FATAL_ERROR "FFX_DOF_SHADERC is '${FFX_DOF_SHADERC}', which does not exist (build ffx-dof-shaderc "
                          "first, or leave FFX_DOF_SHADERC empty to use this build's)")
    endif()
    set(shaderc "${FFX_DOF_SHADERC}")
  elseif(TARGET ffx-dof-shaderc)
    set(shaderc ffx-dof-shaderc)
  else()
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): the ffx-dof-shaderc tool is not part of this build "
                        "(it is built with FFX_DOF_BUILD_VULKAN)")
  endif()
  if(NOT arg_NAMESPACE)
    set(arg_NAMESPACE "ffxdof::shaders::${arg_LANGUAGE}")
  endif()
  if(NOT arg_PERMUTATIONS_JSON)
    get_property(arg_PERMUTATIONS_JSON GLOBAL PROPERTY FFX_DOF_PERMUTATIONS_JSON)
  endif()
  if(NOT arg_SOURCE_DIR)
    set(arg_SOURCE_DIR "${PROJECT_SOURCE_DIR}/shaders_common/entry")
  endif()
  if(NOT arg_INCLUDE_DIRS)
    set(arg_INCLUDE_DIRS "${PROJECT_SOURCE_DIR}/shaders_common")
  endif()
  if(NOT EXISTS "${arg_PERMUTATIONS_JSON}")
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): permutations file '${arg_PERMUTATIONS_JSON}' not found")
  endif()
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${arg_PERMUTATIONS_JSON}")
  file(READ "${arg_PERMUTATIONS_JSON}" json)
  string(JSON pass_count ERROR_VARIABLE json_error LENGTH "${json}" passes)
  if(json_error)
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): ${arg_PERMUTATIONS_JSON}: ${json_error}")
  endif()

  set(common_args --language ${source_language} --namespace ${arg_NAMESPACE} ${dxc_args})
  # FFX_DOF_SHADER_CACHE_DIR: permutations another build (another configuration, commit or build folder) compiled
  # are read back, not compiled again (tools/test.sh: the sanitizer build reads the Release build's).
  if(FFX_DOF_SHADER_CACHE_DIR AND NOT arg_LANGUAGE STREQUAL "dxil")
    list(APPEND common_args --cache-dir "${FFX_DOF_SHADER_CACHE_DIR}")
  endif()
  foreach(dir IN LISTS arg_INCLUDE_DIRS)
    list(APPEND common_args -I ${dir})
  endforeach()
  foreach(define IN LISTS arg_DEFINES)
    list(APPEND common_args --define ${define})
  endforeach()
  foreach(shift IN LISTS arg_HLSL_SHIFTS)
    list(APPEND common_args --hlsl-shift ${shift})
  endforeach()

  set(out_dir "${CMAKE_CURRENT_BINARY_DIR}/${target}")
  set(sources "")
  set(built_passes "")
  math(EXPR last "${pass_count} - 1")
  foreach(i RANGE ${last})
    string(JSON pass GET "${json}" passes ${i} name)
    if(arg_PASSES AND NOT pass IN_LIST arg_PASSES)
      continue()
    endif()
    list(APPEND built_passes ${pass})
    set(source "${arg_SOURCE_DIR}/ffx_dof_${pass}.${source_language}")
    if(NOT EXISTS "${source}")
      message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): the source of pass '${pass}' is missing: ${source}")
    endif()
    set(axis_args "")
    string(JSON axis_count LENGTH "${json}" passes ${i} axes)
    if(axis_count GREATER 0)
      math(EXPR last_axis "${axis_count} - 1")
      foreach(a RANGE ${last_axis})
        string(JSON macro MEMBER "${json}" passes ${i} axes ${a})
        string(JSON value_count LENGTH "${json}" passes ${i} axes ${macro})
        set(values "")
        math(EXPR last_value "${value_count} - 1")
        foreach(v RANGE ${last_value})
          string(JSON value GET "${json}" passes ${i} axes ${macro} ${v})
          list(APPEND values ${value})
        endforeach()
        list(JOIN values "," values)
        list(APPEND axis_args "-D${macro}={${values}}")
      endforeach()
    endif()
    set(stem "ffx_dof_${pass}_${arg_LANGUAGE}")
    add_custom_command(
      OUTPUT "${out_dir}/${stem}.h" "${out_dir}/${stem}.cpp" "${out_dir}/${stem}.json"
      COMMAND ${shaderc} "${source}" --pass ${pass} ${common_args} ${axis_args} -o "${out_dir}"
              --basename ${stem} --depfile "${out_dir}/${stem}.d"
      DEPENDS ${shaderc} "${source}" ${dxc_depends}
      DEPFILE "${out_dir}/${stem}.d"
      COMMENT "ffx-dof-shaderc: all permutations of ${pass} (${arg_LANGUAGE})"
      VERBATIM)
    list(APPEND sources "${out_dir}/${stem}.cpp")
  endforeach()
  foreach(pass IN LISTS arg_PASSES)
    if(NOT pass IN_LIST built_passes)
      message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): pass '${pass}' is not in ${arg_PERMUTATIONS_JSON}")
    endif()
  endforeach()
  if(NOT built_passes)
    message(FATAL_ERROR "ffx_dof_add_shader_library(${target}): no passes in ${arg_PERMUTATIONS_JSON}")
  endif()

  # The aggregate: one header for the target and a lookup by pass name.
  set(table_list "")
  set(includes "")
  foreach(pass IN LISTS built_passes)
    string(APPEND includes "#include \"ffx_dof_${pass}_${arg_LANGUAGE}.h\"\n")
    string(APPEND table_list "    &pass_${pass},\n")
  endforeach()
  list(LENGTH built_passes table_count)
  file(CONFIGURE OUTPUT "${out_dir}/${target}.h" CONTENT
"// Generated by ffx_dof_add_shader_library(${target} LANGUAGE ${arg_LANGUAGE}). Do not edit.
#pragma once

#include \"ffx_dof_shader_table.h\"
${includes}
namespace ${arg_NAMESPACE} {

// One table per pass, in the order of the permutations JSON.
extern const ffxdof::shaders::PassTable* const kPassTables[${table_count}];
constexpr size_t kPassTableCount = ${table_count};

// The table of `pass` (\"blur\", ...), or nullptr when this library has no such pass.
const ffxdof::shaders::PassTable* findPassTable(const char* pass);

}  // namespace ${arg_NAMESPACE}
" @ONLY)
  file(CONFIGURE OUTPUT "${out_dir}/${target}.cpp" CONTENT
"// Generated by ffx_dof_add_shader_library(${target} LANGUAGE ${arg_LANGUAGE}). Do not edit.
#include \"${target}.h\"

namespace ${arg_NAMESPACE} {

extern const ffxdof::shaders::PassTable* const kPassTables[${table_count}] = {
${table_list}};

const ffxdof::shaders::PassTable* findPassTable(const char* pass) {
    return ffxdof::shaders::findPassTable(kPassTables, kPassTableCount, pass);
}

}  // namespace ${arg_NAMESPACE}
" @ONLY)

  add_library(${target} STATIC "${out_dir}/${target}.cpp" ${sources})
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${out_dir}>)
  target_link_libraries(${target} PUBLIC ffx_dof_shader_table)
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON)
  ffx_dof_project_target(${target})
  if(FFX_DOF_INSTALL AND NOT arg_NO_INSTALL)
    # A static backend that links these tables needs them in the export set too.
    install(TARGETS ${target} EXPORT ffx-dof-targets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  endif()
endfunction()

# DXIL for the D3D12 backend, which links ffx_dof_shaders_dxil when it exists (backends/ comes after
# this file). Not in the MinGW cross build: it has no shader compiler (FFX_DOF_BUILD_VULKAN is off
# there, so this file is not included).
if(FFX_DOF_BUILD_DX12 AND (WIN32 OR FFX_DOF_DXC))
  find_program(FFX_DOF_DXC dxc DOC "dxc, the DirectX shader compiler, for the D3D12 backend's DXIL")
  if(FFX_DOF_DXC)
    ffx_dof_add_shader_library(ffx_dof_shaders_dxil LANGUAGE dxil DXC "${FFX_DOF_DXC}")
    set(FFX_DOF_HAVE_DXIL ON CACHE INTERNAL "Whether DXIL shader tables are built")
    message(STATUS "ffx-dof: DXIL from ${FFX_DOF_DXC}")
  else()
    set(FFX_DOF_HAVE_DXIL OFF CACHE INTERNAL "Whether DXIL shader tables are built")
    message(STATUS "ffx-dof: dxc not found (set FFX_DOF_DXC): no DXIL, the D3D12 backend will report UNSUPPORTED")
  endif()
endif()
