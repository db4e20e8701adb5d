# volren_add_library(NAME SOURCES...): a volren plugin library with public headers in include/.
function(volren_add_library name)
  add_library(${name} SHARED ${ARGN})
  add_library(volren::${name} ALIAS ${name})
  set_target_properties(${name} PROPERTIES OUTPUT_NAME volren_${name} VERSION ${PROJECT_VERSION} SOVERSION 0)
  target_include_directories(${name} PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  install(TARGETS ${name} EXPORT volrenTargets
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(DIRECTORY include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
endfunction()

# volren_add_osgdb_plugin(EXT SOURCES...): an osgDB ReaderWriter named osgdb_EXT, placed where
# OSG looks for plugins (LIBDIR/osgPlugins-X) in both the build and the install tree.
function(volren_add_osgdb_plugin ext)
  set(target osgdb_${ext})
  add_library(${target} MODULE ${ARGN})
  set_target_properties(${target} PROPERTIES PREFIX ""
    LIBRARY_OUTPUT_DIRECTORY "${CMAKE_BINARY_DIR}/${CMAKE_INSTALL_LIBDIR}/${VOLREN_OSG_PLUGIN_DIR}"
    INSTALL_RPATH "$ORIGIN/..")
  install(TARGETS ${target} LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}/${VOLREN_OSG_PLUGIN_DIR})
  set_property(GLOBAL APPEND PROPERTY VOLREN_OSGDB_PLUGINS ${target})  # tests depend on them all
endfunction()
