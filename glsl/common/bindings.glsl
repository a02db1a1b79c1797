// Binding points shared by passes (texture units and buffer bindings). Keep in sync with
// renderer/passes/bindings.h, which defines the same numbers for the host.
#define BINDING_SAMPLE_VIEWS 0
#define BINDING_LIGHTS 1
#define BINDING_SAMPLE_LOOKUPS 2
#define BINDING_CASTER_FLAGS 6
#define BINDING_GEOMETRIC_NORMAL 15  // texture unit of the G-buffer geometric normal
#define MAX_SAMPLE_LOOKUPS 1024
