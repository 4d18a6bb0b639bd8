# The Debian package (./scripts/package, docs/install.md): what cmake/install.cmake
# installs, under /usr, with Depends worked out by dpkg-shlibdeps from the programs'
# shared libraries. Nothing runs at install or removal (no maintainer scripts), so
# removing the package leaves nothing behind.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME benchpilot)
set(CPACK_PACKAGE_VENDOR "The BenchPilot authors")
set(CPACK_PACKAGE_CONTACT "The BenchPilot authors <benchpilot@users.noreply.github.com>")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "operate and test laboratory motion instruments / 实验室运动仪器的操作与测试")
# The long description: CPack indents it for the control file and turns an empty
# line into " .", so it is written here as plain paragraphs.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "BenchPilot drives the XYZ dispensing manipulator of an automatic sampling
analyzer, the XY grating-feedback stage of an image-measuring microscope, and
GRBL or grblHAL controllers over a serial port: jog and home, live plots, PID
tuning, sample-plate recipes, stitching scans and accuracy calibration. Both
instruments are simulated, so it can be tried without hardware. It comes with a
command-line program (benchpilot-cli), a simulator on a pseudo-terminal
(benchpilot-sim) and a scripting API with a Python client.

BenchPilot 通过串口控制自动进样分析仪的 XYZ 加样机械手、影像测量显微镜的光栅
反馈 XY 载物台，以及 GRBL 或 grblHAL 控制器：点动与回零、实时曲线、PID 整定、
样品板加样配方、显微拼接扫描与精度标定。两种仪器均有仿真，无需硬件即可试用。
另附命令行程序 benchpilot-cli、伪终端仿真器 benchpilot-sim，以及带 Python
客户端的脚本接口。")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Not a shared-library dependency, so shlibdeps cannot see them: Qt's platform
# plugins (the window, and offscreen screenshots).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
# Qt's own dialogs in Chinese, a Chinese font, and python3 for the client.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n, fonts-wqy-microhei | fonts-noto-cjk, python3")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
set(CPACK_OUTPUT_FILE_PREFIX ${PROJECT_SOURCE_DIR}/dist)
include(CPack)
