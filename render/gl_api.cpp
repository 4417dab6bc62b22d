#include "render/gl_api.hpp"

#include <dlfcn.h>

#include <string>

#include "render/render_error.hpp"

namespace washout::render {
namespace {

using GetProcAddress = decltype(&::OSMesaGetProcAddress);

// By name from the library's exports, else from OSMesa, which hands out every GL entry point.
template <class Function>
void resolve(void* library, GetProcAddress get_proc, const char* name, Function& target) {
  void* found = dlsym(library, name);
  if (!found && get_proc) found = reinterpret_cast<void*>(get_proc(name));
  if (!found)
    throw ContextError(std::string("libOSMesa does not provide ") + name +
                       " (an OpenGL 3.3 core profile is needed)");
  target = reinterpret_cast<Function>(found);
}

GlApi load() {
  void* library = nullptr;
  for (const char* name : {"libOSMesa.so.8", "libOSMesa.so"})
    if ((library = dlopen(name, RTLD_NOW | RTLD_LOCAL))) break;
  if (!library)
    throw ContextError(std::string("cannot load libOSMesa (is libosmesa6 installed?): ") +
                       dlerror());
  const auto get_proc = reinterpret_cast<GetProcAddress>(dlsym(library, "OSMesaGetProcAddress"));
  GlApi api;
  resolve(library, get_proc, "OSMesaCreateContextAttribs", api.OSMesaCreateContextAttribs);
  resolve(library, get_proc, "OSMesaMakeCurrent", api.OSMesaMakeCurrent);
  resolve(library, get_proc, "OSMesaDestroyContext", api.OSMesaDestroyContext);
#define WASHOUT_GL_RESOLVE(name) resolve(library, get_proc, #name, api.name);
  WASHOUT_GL_FUNCTIONS(WASHOUT_GL_RESOLVE)
#undef WASHOUT_GL_RESOLVE
  return api;  // the library stays loaded for the process
}

}  // namespace

const GlApi& gl() {
  static const GlApi api = load();  // a failed load throws, and the next call tries again
  return api;
}

}  // namespace washout::render
