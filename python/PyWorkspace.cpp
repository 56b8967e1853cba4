#include "python/PyWorkspace.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>

#include <pybind11/stl.h>

#include "model/EffectSelection.h"
#include "python/Errors.h"
#include "python/Values.h"
#include "validation/TextureArguments.h"

namespace py = pybind11;

namespace rmfx::python {

PyWorkspace::PyWorkspace(const std::string& path, const std::vector<std::string>& media, const std::string& missingMedia,
                         const std::string& effect, const std::vector<std::pair<std::string, std::string>>& overrides,
                         const std::vector<std::string>& textures, bool sandbox) {
    if (missingMedia != "error" && missingMedia != "placeholder")
        fail("missing_media: expected 'error' or 'placeholder', got '" + missingMedia + "'", "missing_media");
    request_.workspace = path;
    for (const std::string& folder : media) request_.load.media.searchPath.emplace_back(folder);
    request_.load.media.missing = missingMedia == "placeholder" ? MissingMedia::Placeholder : MissingMedia::Error;
    request_.load.media.sandbox = sandbox;
    request_.load.effect = effect;
    for (const std::string& text : textures) {
        Result<TextureArgument> texture = parseTextureArgument(text);
        if (!texture) fail("textures: " + texture.error(), "texture " + text.substr(0, text.find('=')));
        request_.load.textures.push_back(std::move(*texture));
    }
    request_.overrides = overrides;
    Result<LoadedRun> loaded = loadRun(request_);
    if (!loaded) fail(loaded.takeDiagnostics());
    warnings_ = loaded.takeDiagnostics();
    loaded_ = std::move(*loaded);
}

const Variable& PyWorkspace::variable(const std::string& name) const {
    if (const Variable* v = loaded_.ws.findVariable(name)) return *v;
    std::string known;
    for (const Variable& each : loaded_.ws.variables) known += (known.empty() ? "" : ", ") + each.name;
    fail("the workspace has no variable '" + name + "'" + (known.empty() ? " (it declares none)" : " (it has: " + known + ")"),
         "variable " + name);
}

void PyWorkspace::set(const std::string& name, const std::string& text) {
    Workspace& ws = loaded_.ws;
    const Variable* before = ws.findVariable(name);
    const Value old = before ? before->value : Value{};
    Result<void> set = applyOverrides(ws, {{name, text}});
    if (!set) {
        if (Variable* v = ws.findVariable(name)) v->value = old;
        fail(set.takeDiagnostics());
    }
    auto same = [&](const auto& o) { return o.first == name; };
    request_.overrides.erase(std::remove_if(request_.overrides.begin(), request_.overrides.end(), same), request_.overrides.end());
    request_.overrides.emplace_back(name, text);
    ++valuesRevision_;
}

void PyWorkspace::selectEffects(std::optional<std::vector<std::string>> effects) {
    Result<std::set<std::string>> selected = rmfx::selectEffects(loaded_.ws, effects);
    if (!selected) fail("effects: " + selected.error(), "effects");
    effects_ = std::move(effects);
    ++effectsRevision_;
}

namespace {

const char* widgetName(WidgetHint hint) {
    switch (hint) {
        case WidgetHint::Slider: return "slider";
        case WidgetHint::Drag: return "drag";
        case WidgetHint::Color: return "color";
        case WidgetHint::Checkbox: return "checkbox";
        case WidgetHint::Combo: return "combo";
        case WidgetHint::Auto: break;
    }
    return "auto";
}

py::object optionalFloat(const std::optional<float>& v) { return v ? py::object(py::float_(*v)) : py::object(py::none()); }

std::string fspath(const py::object& path) {
    return py::str(py::module_::import("os").attr("fspath")(path)).cast<std::string>();
}

// A snapshot of one variable: what it was when read.
void bindVariable(py::module_& m) {
    py::class_<Variable>(m, "Variable", "A workspace variable as it was when read (set it through the Workspace).")
        .def_readonly("name", &Variable::name)
        .def_property_readonly("type", [](const Variable& v) { return std::string(valueTypeName(v.value.type)); },
                               "float, int, bool, vec2, vec3, vec4, color, mat2, mat3 or mat4")
        .def_property_readonly("components", [](const Variable& v) { return componentCount(v.value.type); })
        .def_property_readonly("value", [](const Variable& v) { return toPython(v.value); },
                               "a float, an int, a bool, or a tuple of floats (matrices column-major)")
        .def_property_readonly("min", [](const Variable& v) { return optionalFloat(v.min); })
        .def_property_readonly("max", [](const Variable& v) { return optionalFloat(v.max); })
        .def_property_readonly("step", [](const Variable& v) { return optionalFloat(v.step); })
        .def_property_readonly("range", [](const Variable& v) -> py::object {
            if (!v.min && !v.max) return py::none();
            return py::make_tuple(optionalFloat(v.min), optionalFloat(v.max));
        }, "(min, max) as the workspace declares them (either may be None); None when it declares neither")
        .def_property_readonly("widget", [](const Variable& v) { return std::string(widgetName(v.widget)); },
                               "auto, slider, drag, color, checkbox or combo")
        .def_readonly("options", &Variable::options, "a combo's labels: value i selects options[i]")
        .def_property_readonly("semantic", [](const Variable& v) -> py::object {
            return v.semantic.empty() ? py::object(py::none()) : py::object(py::str(v.semantic));
        }, "the value the runtime fills each frame (Time0_X, ViewProjection, …), or None")
        .def_readonly("editable", &Variable::editable)
        .def_readonly("hdr", &Variable::hdr, "a colour whose values may exceed 1")
        .def_readonly("description", &Variable::description)
        .def_property_readonly("file", [](const Variable& v) { return v.where.file; })
        .def_property_readonly("line", [](const Variable& v) { return v.where.line; })
        .def("__repr__", [](const Variable& v) {
            return "<rmfx.Variable " + v.name + ": " + valueTypeName(v.value.type) + " = " + formatValue(v.value) + ">";
        });
}

struct EffectView {
    Effect effect;
    bool asked = false;
};

void bindEffect(py::module_& m) {
    py::class_<EffectView>(m, "Effect", "A workspace effect as it was when read.")
        .def_property_readonly("name", [](const EffectView& e) { return e.effect.name; })
        .def_property_readonly("passes", [](const EffectView& e) { return e.effect.passes; })
        .def_property_readonly("switches", [](const EffectView& e) { return e.effect.switches; },
                               "variables that switch it off at run time while all are false or zero")
        .def_property_readonly("source", [](const EffectView& e) -> py::object {
            return e.effect.source.empty() ? py::object(py::none()) : py::object(py::str(e.effect.source));
        })
        .def_property_readonly("description", [](const EffectView& e) { return e.effect.description; })
        .def_property_readonly("selected", [](const EffectView& e) { return e.asked; },
                               "whether the frame computes it (Workspace.effects_selected)")
        .def("__repr__", [](const EffectView& e) {
            return "<rmfx.Effect " + e.effect.name + (e.asked ? "" : " (not selected)") + ">";
        });
}

}  // namespace

void bindWorkspace(py::module_& m) {
    bindVariable(m);
    bindEffect(m);
    py::class_<PyWorkspace, std::shared_ptr<PyWorkspace>>(m, "Workspace",
        "A loaded and validated workspace. ws['Name'] reads a variable's value and ws['Name'] = value sets it (checked "
        "as `rmfx render --set` checks it: rmfx.Error on a wrong name or value). Renderers render what is set.")
        .def_property_readonly("path", [](const PyWorkspace& w) { return w.ws().path.string(); })
        .def_property_readonly("name", [](const PyWorkspace& w) { return w.ws().name; })
        .def_property_readonly("size", [](const PyWorkspace& w) { return py::make_tuple(w.ws().width, w.ws().height); },
                               "(width, height): the size it renders at when no size and no scene image is given")
        .def_property_readonly("variables", [](const PyWorkspace& w) { return w.ws().variables; },
                               "every variable, in file order (snapshots)")
        .def("variable", [](const PyWorkspace& w, const std::string& name) { return w.variable(name); }, py::arg("name"))
        .def("__getitem__", [](const PyWorkspace& w, const std::string& name) { return toPython(w.variable(name).value); })
        .def("__setitem__", [](PyWorkspace& w, const std::string& name, const py::object& value) {
            w.variable(name);  // an unknown name is said as such before its value is read
            w.set(name, valueText(name, value));
        })
        .def("__contains__", [](const PyWorkspace& w, const std::string& name) { return w.ws().findVariable(name) != nullptr; })
        .def("set", [](PyWorkspace& w, const py::kwargs& values) {
            for (auto [key, value] : values) {
                const std::string name = py::str(key).cast<std::string>();
                w.variable(name);
                w.set(name, valueText(name, value));
            }
        }, "set(Name=value, …): sets each in turn; the first bad one raises rmfx.Error (those before it stay set)")
        .def_property_readonly("effects", [](const PyWorkspace& w) {
            Result<std::set<std::string>> asked = selectEffects(w.ws(), w.effects());
            std::vector<EffectView> views;
            for (const Effect& e : w.ws().effects) views.push_back({e, asked && asked->count(e.name) > 0});
            return views;
        })
        .def_property("effects_selected",
            [](const PyWorkspace& w) -> py::object {
                return w.effects() ? py::cast(*w.effects()) : py::object(py::none());
            },
            [](PyWorkspace& w, const std::optional<std::vector<std::string>>& names) { w.selectEffects(names); },
            "the effects asked for, as rmfx render --effects; None: the workspace's <output effects>, else all")
        .def_property_readonly("inputs", [](const PyWorkspace& w) {
            std::vector<std::string> names;
            for (const ImageInput& i : w.ws().inputs) names.push_back(i.name);
            return names;
        }, "the names of its <input>s, which Renderer.render(inputs={name: image}) fills")
        .def_property_readonly("output", [](const PyWorkspace& w) { return w.ws().outputTargetName(); },
                               "the target rendered when render() names none")
        .def_property_readonly("warnings", [](const PyWorkspace& w) { return w.warnings(); })
        .def("__repr__", [](const PyWorkspace& w) { return "<rmfx.Workspace " + w.ws().path.string() + ">"; })
        // Pickled as how it was loaded and what was set since (for Dask and multiprocessing): the
        // other process loads the file again, so it must reach the same path.
        .def(py::pickle(
            [](const PyWorkspace& w) {
                const RunRequest& r = w.request();
                std::vector<std::string> media;
                for (const auto& folder : r.load.media.searchPath) media.push_back(std::filesystem::absolute(folder).string());
                std::vector<std::string> textures;
                for (const TextureArgument& t : r.load.textures) {
                    std::string text = t.name + "=";
                    for (size_t i = 0; i < t.files.size(); ++i)
                        text += (i ? "," : "") + std::filesystem::absolute(t.files[i]).string();
                    textures.push_back(text);
                }
                return py::make_tuple(r.workspace ? std::filesystem::absolute(*r.workspace).string() : std::string(), media,
                                      r.load.media.missing == MissingMedia::Placeholder ? "placeholder" : "error", r.load.effect,
                                      r.overrides, w.effects() ? py::cast(*w.effects()) : py::object(py::none()), textures,
                                      r.load.media.sandbox);
            },
            [](const py::tuple& state) {
                if (state.size() != 8) fail("a pickled rmfx.Workspace of another version", "pickle");
                auto w = std::make_shared<PyWorkspace>(
                    state[0].cast<std::string>(), state[1].cast<std::vector<std::string>>(), state[2].cast<std::string>(),
                    state[3].cast<std::string>(), state[4].cast<std::vector<std::pair<std::string, std::string>>>(),
                    state[6].cast<std::vector<std::string>>(), state[7].cast<bool>());
                if (!state[5].is_none()) w->selectEffects(state[5].cast<std::vector<std::string>>());
                return w;
            }));

    m.def("load", [](const py::object& path, const std::vector<py::object>& media, const std::string& missingMedia,
                     const std::string& effect, const std::optional<py::dict>& textures, bool sandbox, const py::kwargs& overrides) {
        std::vector<std::string> folders;
        for (const py::object& folder : media) folders.push_back(fspath(folder));
        std::vector<std::string> textureTexts;
        if (textures)
            for (auto [key, value] : *textures) {
                const std::string name = py::str(key).cast<std::string>();
                std::string files;
                if (py::isinstance<py::str>(value) || py::hasattr(value, "__fspath__")) {
                    files = fspath(py::reinterpret_borrow<py::object>(value));
                } else if (py::isinstance<py::sequence>(value)) {
                    for (const py::handle& face : py::reinterpret_borrow<py::sequence>(value))
                        files += (files.empty() ? "" : ",") + fspath(py::reinterpret_borrow<py::object>(face));
                } else {
                    fail("textures: '" + name + "' takes a path, or six paths for a cube map's faces", "texture " + name);
                }
                textureTexts.push_back(name + "=" + files);
            }
        std::vector<std::pair<std::string, std::string>> values;
        for (auto [key, value] : overrides) {
            const std::string name = py::str(key).cast<std::string>();
            values.emplace_back(name, valueText(name, value));
        }
        return std::make_shared<PyWorkspace>(fspath(path), folders, missingMedia, effect, values, textureTexts, sandbox);
    }, py::arg("path"), py::kw_only(), py::arg("media") = std::vector<py::object>{}, py::arg("missing_media") = "error",
       py::arg("effect") = "", py::arg("textures") = py::none(), py::arg("sandbox") = false,
       "load(path, *, media=[], missing_media='error', effect='', textures=None, sandbox=False, **overrides) -> Workspace\n\n"
       "textures: {name: path} (or six paths +x, -x, +y, -y, +z, -z for a cube map) in place of the textures' own files, "
       "as rmfx render --texture. sandbox: no reference may lead outside the workspace's folder and `media` (rmfx "
       "render --sandbox).\n\n"
       "Loads and validates an rmfx workspace (.xml) or a RenderMonkey .rfx file (effect: which of its effects; '' the "
       "active one). media: folders searched for referenced files after the workspace's own; missing_media: 'error' or "
       "'placeholder' (a stand-in and a warning). Name=value keyword arguments set variables, as rmfx render --set. "
       "Raises rmfx.Error with the file, line and element of the first problem.");
}

}  // namespace rmfx::python
