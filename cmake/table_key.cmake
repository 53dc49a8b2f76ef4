# OBSCURA_TABLE_KEY names the tables the library fits at run time and keeps between runs in the
# cache folder (src/obscura/math/disk_cache.h) by what made them: the code that fits or
# prefilters them and what it reads (src/obscura/color/, src/obscura/math/, src/obscura/film/image*,
# src/obscura/shading/, the rasterizer's environment lighting, data/color/), the compiler and its
# flags. An edit to
# any of those files re-runs CMake (CMAKE_CONFIGURE_DEPENDS) and changes the key, so no run ever
# reads a table that other code made. Only the files that name cache entries
# get the definition: a new key recompiles those alone.
file(GLOB OBSCURA_TABLE_KEY_FILES
     ${PROJECT_SOURCE_DIR}/src/obscura/color/* ${PROJECT_SOURCE_DIR}/src/obscura/math/*
     ${PROJECT_SOURCE_DIR}/src/obscura/film/image.* ${PROJECT_SOURCE_DIR}/data/color/*
     ${PROJECT_SOURCE_DIR}/src/obscura/raster/environment_lighting.*
     ${PROJECT_SOURCE_DIR}/src/obscura/shading/*)
list(SORT OBSCURA_TABLE_KEY_FILES)
string(TOUPPER "${CMAKE_BUILD_TYPE}" build_type)
set(key_text "${CMAKE_CXX_COMPILER_ID} ${CMAKE_CXX_COMPILER_VERSION} ${CMAKE_CXX_FLAGS} "
             "${CMAKE_CXX_FLAGS_${build_type}} ${OBSCURA_SANITIZE} ${OBSCURA_FUZZ}")
foreach(file ${OBSCURA_TABLE_KEY_FILES})
  set_property(DIRECTORY ${PROJECT_SOURCE_DIR} APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS "${file}")
  file(SHA1 "${file}" file_hash)
  string(APPEND key_text " ${file_hash}")
endforeach()
string(SHA1 key "${key_text}")
string(SUBSTRING "${key}" 0 16 key)
set_source_files_properties(${PROJECT_SOURCE_DIR}/src/obscura/color/rgb_to_spectrum.cpp
                            ${PROJECT_SOURCE_DIR}/src/obscura/raster/environment_lighting.cpp
                            ${PROJECT_SOURCE_DIR}/src/obscura/shading/ggx_energy.cpp
                            ${PROJECT_SOURCE_DIR}/src/obscura/shading/phong_albedo.cpp
                            ${PROJECT_SOURCE_DIR}/src/obscura/shading/charlie_sheen.cpp
                            PROPERTIES COMPILE_DEFINITIONS OBSCURA_TABLE_KEY="${key}")
