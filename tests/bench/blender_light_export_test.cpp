// The export of scenes/lights_peer.json's point, spot and distant lights, run without Blender: the
// script's own light() executes against a stand-in for bpy that records what it sets, and the
// result, read as Cycles 3.4's kernel reads a light (kernel/light/light.h: a point or spot of
// radius 0 emits energy/(4π) W/sr; spot_light_attenuation), must emit raylab's intensity.
#include "bench/blender_export.h"
#include "scene/scene_loader.h"
#include "shaders/include/analytic_lights.glsl"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <unistd.h>

using namespace raylab;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;

// Runs the script's prelude (its functions) and its light() calls with stand-ins for bpy and
// mathutils; prints per light the attributes the script assigned, where it points, and the
// emission strength its node graph gives for normals at 0 to 40 degrees from that direction.
const char* kStub = R"PY(
import json, math, sys, types

class NodeSocket:
    def __init__(self, node, name, kind, value=None):
        self.node, self.name, self.type, self.default_value, self.source = node, name, kind, value, None

class Sockets(list):
    def __getitem__(self, key):
        if isinstance(key, str):
            return next(s for s in self if s.name == key)
        return list.__getitem__(self, key)

LAYOUT = {
    "ShaderNodeVectorMath": ([("Vector", "VECTOR", (0.0, 0.0, 0.0))] * 3 + [("Scale", "VALUE", 1.0)],
                             [("Vector", "VECTOR"), ("Value", "VALUE")]),
    "ShaderNodeMath": ([("Value", "VALUE", 0.5)] * 3, [("Value", "VALUE")]),
    "ShaderNodeNewGeometry": ([], [("Position", "VECTOR"), ("Normal", "VECTOR")]),
    "ShaderNodeEmission": ([("Color", "RGBA", (1.0, 1.0, 1.0, 1.0)), ("Strength", "VALUE", 1.0)], [("Emission", "SHADER")]),
}

class Node:
    def __init__(self, kind):
        self.kind, self.operation = kind, None
        inputs, outputs = LAYOUT[kind]
        self.inputs = Sockets(NodeSocket(self, n, t, v) for n, t, v in inputs)
        self.outputs = Sockets(NodeSocket(self, n, t) for n, t in outputs)

class Nodes(dict):
    def new(self, kind):
        return Node(kind)

class Links:
    def new(self, a, b):
        b.source = a

class Tree:
    def __init__(self):
        self.nodes = Nodes(Emission=Node("ShaderNodeEmission"))
        self.links = Links()

def value(socket, normal):
    if socket.source is None:
        return socket.default_value
    node, out = socket.source.node, socket.source.name
    if node.kind == "ShaderNodeNewGeometry" and out == "Normal":
        return normal
    a = [value(s, normal) for s in node.inputs]
    if node.kind == "ShaderNodeVectorMath" and node.operation == "DOT_PRODUCT" and out == "Value":
        return sum(x * y for x, y in zip(a[0], a[1]))
    if node.kind == "ShaderNodeMath" and node.operation == "DIVIDE":
        return a[0] / a[1] if a[1] != 0 else 0.0   # Cycles' safe division
    raise ValueError("the stand-in cannot evaluate %s %s" % (node.kind, node.operation))

class LightData:
    def __init__(self, name, kind):
        object.__setattr__(self, "assigned", {"name": name, "type": kind})
        object.__setattr__(self, "node_tree", Tree())
    def __setattr__(self, key, v):
        self.assigned[key] = list(v) if isinstance(v, (tuple, list)) else v

class Object:
    def __init__(self, name, data):
        self.name, self.data = name, data

class Vector(tuple):
    def __new__(cls, v):
        return tuple.__new__(cls, (float(x) for x in v))
    def normalized(self):
        n = math.sqrt(sum(x * x for x in self))
        return Vector(x / n for x in self)
    def to_track_quat(self, track, up):
        return Track(self, track)

class Matrix:
    Rotation = staticmethod(lambda *args: None)

class Track:
    def __init__(self, v, track):
        self.v, self.track = v, track
    def to_euler(self):
        return self

linked = []
bpy = types.ModuleType("bpy")
bpy.types = types.SimpleNamespace(NodeSocket=NodeSocket)
bpy.data = types.SimpleNamespace(lights=types.SimpleNamespace(new=LightData), objects=types.SimpleNamespace(new=Object))
bpy.context = types.SimpleNamespace(scene=types.SimpleNamespace(
    collection=types.SimpleNamespace(objects=types.SimpleNamespace(link=linked.append))))
mathutils = types.ModuleType("mathutils")
mathutils.Vector, mathutils.Matrix = Vector, Matrix
sys.modules["bpy"], sys.modules["mathutils"] = bpy, mathutils

lines = open(sys.argv[1]).read().splitlines()
body = lines.index("clear_scene()")
code = lines[:body] + [l for l in lines[body:] if l.startswith("light(")]
exec(compile("\n".join(code), sys.argv[1], "exec"), {"__name__": "exported"})

out = []
for obj in linked:
    d = obj.data
    axis = Vector(obj.rotation_euler.v).normalized()
    assert obj.rotation_euler.track == "-Z"
    side = Vector((0.0, 0.0, 1.0) if abs(axis[2]) < 0.9 else (1.0, 0.0, 0.0))
    perp = Vector((side[1] * axis[2] - side[2] * axis[1], side[2] * axis[0] - side[0] * axis[2],
                   side[0] * axis[1] - side[1] * axis[0])).normalized()
    strength = []
    for k in range(81):
        t = math.radians(0.5 * k)
        n = tuple(math.cos(t) * a + math.sin(t) * p for a, p in zip(axis, perp))
        s = value(d.node_tree.nodes["Emission"].inputs["Strength"], n) if d.assigned.get("use_nodes") else 1.0
        strength.append([0.5 * k, s])
    out.append({"light": d.assigned, "location": list(obj.location), "shines": list(axis), "strength": strength})
print(json.dumps(out))
)PY";

fs::path scratch() {
    fs::path d = fs::temp_directory_path() / ("raylab_light_export_" + std::to_string(::getpid()));
    fs::create_directories(d);
    return d;
}

// The lights as the stand-in saw the script make them.
nlohmann::json exportedLights(const Scene& scene) {
    const fs::path dir = scratch(), script = dir / "lights.py", stub = dir / "stub.py", out = dir / "lights.json";
    std::ofstream(script) << blenderScript(scene);
    std::ofstream(stub) << kStub;
    const std::string cmd = "python3 '" + stub.string() + "' '" + script.string() + "' > '" + out.string() + "'";
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    std::ifstream in(out);
    nlohmann::json j = nlohmann::json::parse(in, nullptr, false);
    fs::remove_all(dir);
    return j;
}

// raylab (y up) to Blender (z up), as the export places everything.
glm::dvec3 blender(glm::vec3 p) { return glm::dvec3(p.x, -p.z, p.y); }

glm::dvec3 vec3(const nlohmann::json& a) { return glm::dvec3(a.at(0).get<double>(), a.at(1).get<double>(), a.at(2).get<double>()); }

// What Cycles 3.4 emits in W/sr from a point or spot light: colour · energy / (4π).
glm::dvec3 cyclesIntensity(const nlohmann::json& light) {
    return vec3(light.at("color")) * light.at("energy").get<double>() / (4.0 * kPi);
}

// kernel/light/common.h spot_light_attenuation, with scene/light.cpp's spot_angle = cos(size/2)
// and spot_smooth = (1 − spot_angle)·blend.
double cyclesSpotAttenuation(double cosTheta, double spotSize, double spotBlend) {
    const double spotAngle = std::cos(spotSize / 2.0), smooth = (1.0 - spotAngle) * spotBlend;
    if (cosTheta <= spotAngle) return 0.0;
    const double t = cosTheta - spotAngle;
    double a = cosTheta;
    if (t < smooth && smooth != 0.0) {
        const double f = t / smooth;
        a *= 3.0 * f * f - 2.0 * f * f * f;
    }
    return a;
}

void expectNear(glm::dvec3 got, glm::dvec3 want, double rel, const std::string& what) {
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(got[c], want[c], rel * std::max(1e-3, std::abs(want[c]))) << what << ", channel " << c;
}

TEST(BlenderLightExport, LightsPeerSceneGivesCyclesRaylabsIntensityFalloffAndSunDisc) {
    const Scene scene = loadScene(std::string(RAYLAB_SOURCE_DIR) + "/scenes/lights_peer.json");
    ASSERT_EQ(scene.lights.size(), 4u);
    const nlohmann::json lights = exportedLights(scene);
    ASSERT_TRUE(lights.is_array()) << lights;
    ASSERT_EQ(lights.size(), scene.lights.size()) << lights;
    constexpr double kRel = 2e-6;   // the script's numbers have 7 significant digits

    {
        SCOPED_TRACE("a point light of radius 0 and raylab's intensity");
        const Light& l = scene.lights[0];
        ASSERT_EQ(l.type, Light::Type::Point);
        const nlohmann::json& p = lights[0]["light"];
        EXPECT_EQ(p.at("type"), "POINT");
        EXPECT_EQ(p.at("shadow_soft_size"), 0.0) << "a sphere of radius > 0 is no delta light";
        EXPECT_NEAR(p.at("energy").get<double>(), 4.0 * kPi * 6.0, 1e-5) << "power 4πI of the brightest channel";
        expectNear(cyclesIntensity(p), glm::dvec3(l.intensity), kRel, "I");
        expectNear(vec3(lights[0]["location"]), blender(l.position), kRel, "position");
        EXPECT_FALSE(p.value("use_nodes", false));
    }
    {
        SCOPED_TRACE("a spot of radius 0 whose cone, rim and axis intensity are raylab's at every angle");
        const Light& l = scene.lights[1];
        ASSERT_EQ(l.type, Light::Type::Spot);
        const nlohmann::json& s = lights[1]["light"];
        EXPECT_EQ(s.at("type"), "SPOT");
        EXPECT_EQ(s.at("shadow_soft_size"), 0.0);
        const double size = s.at("spot_size").get<double>(), blend = s.at("spot_blend").get<double>();
        EXPECT_NEAR(size, 2.0 * 26.0 * kPi / 180.0, 1e-6) << "the full cone angle: twice the outer angle";
        const double co = std::cos(26.0 * kPi / 180.0), ci = std::cos(18.0 * kPi / 180.0);
        EXPECT_NEAR(blend, (ci - co) / (1.0 - co), 1e-6);
        expectNear(vec3(lights[1]["location"]), blender(l.position), kRel, "position");
        expectNear(vec3(lights[1]["shines"]), glm::normalize(blender(l.direction)), kRel, "axis");
        const glm::dvec3 onAxis = cyclesIntensity(s);
        int lit = 0, dark = 0;
        for (const nlohmann::json& at : lights[1]["strength"]) {
            const double theta = at[0].get<double>() * kPi / 180.0, strength = at[1].get<double>();
            const double cycles = cyclesSpotAttenuation(std::cos(theta), size, blend) * strength;
            const double raylab = double(glsl::spotFalloff(float(std::cos(theta)), float(co), float(ci)));
            (raylab > 0.0 ? lit : dark) += 1;
            // Within 1e-5 of the peak: spotFalloff runs in float, whose cos θ near the rim
            // carries ~1e-7 of the (cos inner − cos outer) ≈ 0.05 it divides by.
            for (int c = 0; c < 3; ++c)
                EXPECT_NEAR(onAxis[c] * cycles, double(l.intensity[c]) * raylab, 1e-5 * double(l.intensity[c]))
                    << "at " << at[0].get<double>() << " degrees from the axis, channel " << c;
        }
        EXPECT_GT(lit, 40) << "inside the cone";
        EXPECT_GT(dark, 20) << "beyond it";
    }
    for (int i : {2, 3}) {
        SCOPED_TRACE("a sun of raylab's irradiance, direction and angular diameter, light " + std::to_string(i));
        const Light& l = scene.lights[size_t(i)];
        ASSERT_EQ(l.type, Light::Type::Distant);
        const nlohmann::json& d = lights[size_t(i)]["light"];
        EXPECT_EQ(d.at("type"), "SUN");
        const double angle = d.at("angle").get<double>();
        EXPECT_NEAR(angle, 2.0 * double(l.angularRadius) * kPi / 180.0, 1e-7) << "Blender's angle is the disc's diameter";
        // Cycles' disc (light_sample, LIGHT_DISTANT) draws directions uniformly on a tangent disc
        // of radius R = tan(angle/2), each of weight colour·energy: a facing surface receives
        // that times the mean cosine 2(√(1 + R²) − 1)/R², 1 for a delta sun.
        const double R = std::tan(angle / 2.0), meanCos = R > 0.0 ? 2.0 * (std::sqrt(1.0 + R * R) - 1.0) / (R * R) : 1.0;
        expectNear(vec3(d.at("color")) * d.at("energy").get<double>() * meanCos, glm::dvec3(l.irradiance), kRel,
                   "irradiance on a surface facing the sun");
        expectNear(vec3(lights[size_t(i)]["shines"]), glm::normalize(blender(l.direction)), kRel, "direction");
    }
    EXPECT_EQ(scene.lights[2].angularRadius, 5.0f);
    EXPECT_EQ(scene.lights[3].angularRadius, 0.0f) << "one sun is a delta light";
}

} // namespace
