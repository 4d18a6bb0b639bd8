# Build speed on a fresh machine (docs/testing.md). CI compiles every
# target once from nothing; these two options make that cheap. A developer's
# default build leaves them off, so an edit recompiles one file and a missing
# #include shows at once (./scripts/test turns both on).
#
#  BP_UNITY  the libraries compile from batches of their sources: Qt's, Eigen's and
#            QCustomPlot's headers are parsed once a batch instead of once a file
#            (3-4x less CPU for the widgets). Names in anonymous namespaces must
#            therefore be unique within a target; shared helpers go in headers.
#  BP_PCH    the test programs precompile gtest and the Qt Core headers they all
#            include (about 1.5 s of parsing a file at -O3). Tests stay out of the
#            unity batches: fixtures and helpers of the same name are the norm there.
option(BP_UNITY "Compile the libraries as unity batches (CI)" OFF)
option(BP_PCH "Precompile the test programs' common headers (CI)" OFF)

function(bp_unity target)
  if(BP_UNITY)
    set_target_properties(${target} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE 12)
  endif()
endfunction()

# Qt's headers only where the program links Qt (test_motion tests plain C++).
function(bp_test_pch target)
  if(NOT BP_PCH)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE
    <gtest/gtest.h> <vector> <string> <memory> <optional> <functional> <algorithm> <cmath>)
  get_target_property(libs ${target} LINK_LIBRARIES)
  if(libs MATCHES "device|wording|_lib|Qt6::")
    target_precompile_headers(${target} PRIVATE
      <QCoreApplication> <QString> <QStringList> <QObject> <QTimer> <QJsonDocument>
      <QJsonObject> <QJsonArray> <QTemporaryDir> <QFile> <QDir>)
  endif()
endfunction()
