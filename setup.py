"""Builds the Python package `drm` with CMake: the extension drm._drm is the
target drm_python of the project's own build (python/CMakeLists.txt), made
for the Python running pip. DRM_BUILD_DIR names the CMake build folder (an
existing one is only brought up to date); by default it is build-python/ in
the clone, so that a second install only builds what changed."""
import os
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))


def version():
    with open(os.path.join(HERE, "CMakeLists.txt"), encoding="utf-8") as f:
        return re.search(r"project\(drm VERSION ([0-9.]+)", f.read()).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = os.path.abspath(os.environ.get("DRM_BUILD_DIR") or os.path.join(HERE, "build-python"))
        if not os.path.exists(os.path.join(build_dir, "CMakeCache.txt")):
            generator = ["-G", "Ninja"] if shutil.which("ninja") else []
            subprocess.run(["cmake", "-S", HERE, "-B", build_dir, *generator, "-DCMAKE_BUILD_TYPE=Release",
                            "-DDRM_BUILD_TESTS=OFF", "-DDRM_BUILD_PLUGINS=OFF",
                            f"-DDRM_PYTHON_EXECUTABLE={sys.executable}"], check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", build_dir, "--target", "drm_python", "-j", jobs], check=True)
        package = os.path.join(build_dir, "python", "drm")
        built = [n for n in os.listdir(package) if n.startswith("_drm.") and n.endswith(".so")]
        if len(built) != 1:
            raise RuntimeError(f"expected one extension in {package}, found {built}")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(os.path.join(package, built[0]), target)


setup(
    version=version(),
    packages=["drm"],
    package_dir={"": "python"},
    package_data={"drm": ["py.typed", "_drm.pyi"]},
    ext_modules=[Extension("drm._drm", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
