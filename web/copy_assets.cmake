# Run by the report_assets target (CMakeLists.txt beside this file).
file(MAKE_DIRECTORY ${OUT_DIR})
set(libraries
  node_modules/three/build/three.module.min.js
  node_modules/three/examples/jsm/controls/OrbitControls.js
  node_modules/chart.js/dist/chart.umd.min.js)
foreach(library ${libraries})
  get_filename_component(name ${library} NAME)
  if(EXISTS ${SOURCE_DIR}/${library})
    file(COPY_FILE ${SOURCE_DIR}/${library} ${OUT_DIR}/${name} ONLY_IF_DIFFERENT)
  endif()
endforeach()
# One strict-mode scope for the page's own files.
set(script "(function () {\n'use strict';\n")
foreach(part ${SCRIPTS})
  file(READ ${part} text)
  string(APPEND script "${text}\n")
endforeach()
string(APPEND script "})();\n")
file(WRITE ${OUT_DIR}/report.js.new "${script}")
file(COPY_FILE ${OUT_DIR}/report.js.new ${OUT_DIR}/report.js ONLY_IF_DIFFERENT)
file(REMOVE ${OUT_DIR}/report.js.new)
file(COPY_FILE ${SOURCE_DIR}/report.css ${OUT_DIR}/report.css ONLY_IF_DIFFERENT)
