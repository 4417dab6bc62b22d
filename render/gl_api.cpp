#include "render/gl_api.hpp"

#include <dlfcn.h>

#include <string>

#include "render/render_error.hpp"

namespace washout::render {
namespace {

template <class Function>
void resolve(void* library, const char* name, Function& target) {
  // OSMesa hands out every GL entry point; dlsym finds those the library exports by name.
  using GetProc = decltype(&::OSMesaGetProcAddress);
  static const auto get_proc = reinterpret_cast<GetProc>(dlsym(library, "OSMesaGetProcAddress"));
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
  GlApi api;
  resolve(library, "OSMesaCreateContextAttribs", api.OSMesaCreateContextAttribs);
  resolve(library, "OSMesaMakeCurrent", api.OSMesaMakeCurrent);
  resolve(library, "OSMesaDestroyContext", api.OSMesaDestroyContext);
#define WASHOUT_GL_RESOLVE(name) resolve(library, #name, api.name);
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
