# `cpack -G DEB` (run in the build folder): a .deb of what `cmake --install` puts in place (bin/shadowlab and
# share/shadowlab), under /usr. Its Depends are the Debian packages of the shared libraries the binary links, as
# dpkg-shlibdeps finds them (dpkg-dev, file), plus the few it loads with dlopen, which no tool can see.
set(CPACK_PACKAGE_NAME shadowlab)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "ShadowLab")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "shadow-map tuning tool: see acne and Peter Panning, measure, fix the bias")
string(CONCAT CPACK_PACKAGE_DESCRIPTION  # Debian wraps nothing: lines under 80 columns
  "ShadowLab renders a scene with the classic two-pass shadow map and shows,\n"
  "measures and explains every setting that decides between shadow acne and\n"
  "Peter Panning: depth and slope bias, normal offset, resolution, filtering,\n"
  "the light's projection. The editor (Dear ImGui) and the command line (render,\n"
  "measure, tune, sweep, export to D3D12 / D3D11 / Vulkan / OpenGL) run on a GPU\n"
  "or on Mesa's llvmpipe.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "ShadowLab maintainers <maintainers@users.noreply.h-seed-d24cfb02.example>"
  CACHE STRING "the .deb's Maintainer field")
set(CPACK_DEBIAN_PACKAGE_SECTION graphics)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # shadowlab_0.1.0_amd64.deb
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# Loaded with dlopen, so dpkg-shlibdeps cannot see them: libEGL.so.1 (glad, headless; libegl1 brings Mesa's EGL),
# libGL.so.1 (GLFW's GLX, the editor) and Mesa's DRI drivers, llvmpipe among them: what renders where there is no GPU.
# shlibdeps' list is added to these.
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libegl1, libgl1, libgl1-mesa-dri")
# The editor's font (it falls back to ImGui's built-in one); assimp-testmodels: two of `shadowlab hardcases`' scenes.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "fonts-dejavu-core")
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "assimp-testmodels, xvfb")
set(CPACK_STRIP_FILES ON)
# cpack packages what is built: it does not build the tests first (package the `shadowlab` target's build).
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
include(CPack)
