#include "io/spring_bone_simulation.hpp"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "inkshade/error.hpp"
#include "io/unit_vector_rotation.hpp"

namespace inkshade::io {

namespace {

glm::dmat4 compose(const NodeTrs& n) { return n.matrix(); }

glm::dvec3 position(const glm::dmat4& m) { return glm::dvec3(m[3]); }
glm::dvec3 point(const glm::dmat4& m, const glm::dvec3& p) { return glm::dvec3(m * glm::dvec4(p, 1.0)); }

// three.js's Vector3.normalize: a zero vector stays zero.
glm::dvec3 normalized(const glm::dvec3& v) {
    const double l = glm::length(v);
    return v / (l > 0.0 ? l : 1.0);
}

// three.js's Vector3.transformDirection: the upper 3x3, normalised.
glm::dvec3 direction(const glm::dmat4& m, const glm::dvec3& v) { return normalized(glm::dmat3(m) * v); }

// How far `tail` (with radius `hit`) is outside the collider (negative: inside) and, when
// inside, the unit direction out of it: three-vrm's VRMSpringBoneColliderShapeSphere and
// ...Capsule.calculateCollision, `matrix` the collider node's world matrix.
double collision(const SpringCollider& c, const glm::dmat4& matrix, const glm::dvec3& tail, double hit,
                 glm::dvec3& out) {
    const glm::dvec3 head = point(matrix, c.offset);  // three-vrm's colliderMatrix position
    out = tail - head;
    if (c.capsule) {
        const glm::dvec3 axis = glm::dmat3(matrix) * (c.tail - c.offset);
        const double length_sq = glm::dot(axis, axis), dot = glm::dot(axis, out);
        if (dot <= 0.0) {
        } else if (length_sq <= dot) {
            out -= axis;
        } else {
            out -= axis * (dot / length_sq);
        }
    }
    const double length = glm::length(out);
    const double distance = length - hit - c.radius;
    if (distance < 0.0) out = length > 0.0 ? out / length : glm::dvec3(0.0);
    return distance;
}

class Simulation {
public:
    Simulation(const SpringBones& bones, const std::vector<int>& parent, const std::vector<NodeTrs>& rest,
               const std::string& path)
        : bones_(bones),
          parent_(parent),
          local_(rest),
          world_(rest.size(), glm::dmat4(1.0)),
          joints_at_(rest.size()),
          state_(bones.joints.size()) {
        for (size_t j = 0; j < bones.joints.size(); ++j) joints_at_[size_t(bones.joints[j].node)].push_back(j);
        order_nodes(path);
        sort_joints();
        for (size_t n : topological_) refresh(n);
        for (size_t j : order_) init(j);
    }

    void step(double delta, std::vector<NodeTrs>& frame) {
        for (size_t n = 0; n < local_.size(); ++n) {
            if (joints_at_[n].empty()) {
                local_[n] = frame[n];
                continue;
            }
            local_[n].t = frame[n].t;  // the animation's rotation, where it sets one, until the joint's replaces it
            local_[n].s = frame[n].s;
            if (frame[n].rotation_animated) local_[n].r = frame[n].r;
        }
        // VRMSpringBoneManager.update: the joints' ancestors and colliders, then each joint
        // with the nodes below it up to the next joints.
        for (size_t n : topological_)
            if (!under_joint_[n]) refresh(n);
        for (size_t j : order_) {
            const size_t node = size_t(bones_.joints[j].node);
            refresh(node);
            update(j, delta);
            refresh(node);
            refresh_below(node);
        }
    }

    // The joints' rotations so far into `frame` (what three.js holds before the next update).
    void current_rotations(std::vector<NodeTrs>& frame) const {
        for (const SpringJoint& j : bones_.joints) frame[size_t(j.node)].r = local_[size_t(j.node)].r;
    }

    std::vector<std::optional<glm::dquat>> rotations() const {
        std::vector<std::optional<glm::dquat>> out(local_.size());
        for (const SpringJoint& j : bones_.joints) out[size_t(j.node)] = local_[size_t(j.node)].r;
        return out;
    }

private:
    struct State {
        glm::dvec3 current_tail{0.0}, prev_tail{0.0}, bone_axis{0.0}, child_position{0.0};
        glm::dmat4 initial_local{1.0};
        glm::dquat initial_rotation{1.0, 0.0, 0.0, 0.0};
    };

    const glm::dmat4& parent_world(size_t node) const {
        static const glm::dmat4 identity(1.0);
        return parent_[node] >= 0 ? world_[size_t(parent_[node])] : identity;
    }
    void refresh(size_t node) { world_[node] = parent_world(node) * compose(local_[node]); }
    glm::dmat4 center_to_world(const SpringJoint& j) const {
        return j.center >= 0 ? world_[size_t(j.center)] : glm::dmat4(1.0);
    }

    // three-vrm's traverseChildrenUntilConditionMet(bone, _relevantChildrenUpdated).
    void refresh_below(size_t node) {
        std::vector<size_t> stack = {node};
        while (!stack.empty()) {
            const size_t n = stack.back();
            stack.pop_back();
            for (size_t c : children_[n])
                if (joints_at_[c].empty()) {
                    refresh(c);
                    stack.push_back(c);
                }
        }
    }

    // Parents before children; nodes in a cycle are left out (an error where a joint needs them).
    void order_nodes(const std::string& path) {
        const size_t n = parent_.size();
        children_.assign(n, {});
        under_joint_.assign(n, false);
        std::vector<size_t> stack;
        for (size_t i = 0; i < n; ++i) {
            if (parent_[i] >= 0)
                children_[size_t(parent_[i])].push_back(i);
            else
                stack.push_back(i);
        }
        std::vector<bool> reached(n, false);
        while (!stack.empty()) {
            const size_t i = stack.back();
            stack.pop_back();
            reached[i] = true;
            topological_.push_back(i);
            under_joint_[i] = !joints_at_[i].empty() || (parent_[i] >= 0 && under_joint_[size_t(parent_[i])]);
            for (size_t c : children_[i]) stack.push_back(c);
        }
        auto check = [&](int node, const char* what) {
            if (node >= 0 && !reached[size_t(node)])
                throw InputError(path, std::string("spring bone ") + what + " node " + std::to_string(node) +
                                           " lies in a cycle of the node hierarchy");
        };
        for (const SpringJoint& j : bones_.joints) {
            check(j.node, "joint");
            check(j.child, "joint tail");
            check(j.center, "center");
        }
        for (const SpringCollider& c : bones_.colliders) check(c.node, "collider");
    }

    // VRMSpringBoneManager._sortJoints: each joint after the joints above its parent and above
    // its colliders (a joint met again while its own dependencies are sorted is skipped, as
    // three-vrm skips a circular dependency).
    void sort_joints() {
        std::vector<char> tried(bones_.joints.size(), 0), done(bones_.joints.size(), 0);
        std::function<void(size_t)> insert = [&](size_t j) {
            if (done[j] || tried[j]) return;
            tried[j] = 1;
            const SpringJoint& joint = bones_.joints[j];
            std::vector<int> deps;  // a Set: the parent, then each collider's node, once
            auto add = [&](int node) {
                if (node >= 0 && std::find(deps.begin(), deps.end(), node) == deps.end()) deps.push_back(node);
            };
            add(parent_[size_t(joint.node)]);
            for (int c : joint.colliders) add(bones_.colliders[size_t(c)].node);
            for (int dep : deps) {
                std::vector<size_t> chain;  // root first
                for (int at = dep; at >= 0; at = parent_[size_t(at)]) chain.insert(chain.begin(), size_t(at));
                for (size_t a : chain)
                    for (size_t other : joints_at_[a]) insert(other);
            }
            order_.push_back(j);
            done[j] = 1;
        };
        for (size_t j = 0; j < bones_.joints.size(); ++j) insert(j);
    }

    // VRMSpringBoneJoint.setInitState.
    void init(size_t j) {
        const SpringJoint& joint = bones_.joints[j];
        const size_t node = size_t(joint.node);
        State& s = state_[j];
        s.initial_local = compose(local_[node]);
        s.initial_rotation = local_[node].r;
        s.child_position = joint.child >= 0 ? local_[size_t(joint.child)].t : normalized(local_[node].t) * 0.07;
        s.current_tail = point(glm::inverse(center_to_world(joint)), point(world_[node], s.child_position));
        s.prev_tail = s.current_tail;
        s.bone_axis = normalized(s.child_position);
    }

    // VRMSpringBoneJoint.update (with _calcWorldSpaceBoneLength and _collision).
    void update(size_t j, double delta) {
        if (delta <= 0.0) return;
        const SpringJoint& joint = bones_.joints[j];
        const size_t node = size_t(joint.node);
        State& s = state_[j];
        const glm::dvec3 head = position(world_[node]);
        const glm::dvec3 child =
            joint.child >= 0 ? position(world_[size_t(joint.child)]) : point(world_[node], s.child_position);
        const double length = glm::length(head - child);
        const glm::dvec3 axis = direction(parent_world(node), direction(s.initial_local, s.bone_axis));
        const glm::dmat4 to_world = center_to_world(joint);
        glm::dvec3 next = point(to_world, s.current_tail + (s.current_tail - s.prev_tail) * (1.0 - joint.drag_force));
        next += axis * (joint.stiffness * delta) + joint.gravity_dir * (joint.gravity_power * delta);
        next = normalized(next - head) * length + head;
        for (int c : joint.colliders) {
            const SpringCollider& collider = bones_.colliders[size_t(c)];
            glm::dvec3 out;
            const double distance = collision(collider, world_[size_t(collider.node)], next, joint.hit_radius, out);
            if (distance >= 0.0) continue;
            next += out * -distance;
            const double l = glm::length(next - head);
            if (l > 0.0) next = (next - head) * (length / l) + head;
        }
        s.prev_tail = s.current_tail;
        s.current_tail = point(glm::inverse(to_world), next);
        const glm::dmat4 initial_inverse = glm::inverse(parent_world(node) * s.initial_local);
        const glm::dvec3 to = normalized(point(initial_inverse, next));
        local_[node].r = s.initial_rotation * from_unit_vectors(s.bone_axis, to);
    }

    const SpringBones& bones_;
    const std::vector<int>& parent_;
    std::vector<NodeTrs> local_;
    std::vector<glm::dmat4> world_;  // three.js's matrixWorld: stale where three-vrm leaves it stale
    std::vector<std::vector<size_t>> joints_at_, children_;
    std::vector<bool> under_joint_;  // a joint's node or below one
    std::vector<size_t> topological_, order_;
    std::vector<State> state_;
};

}  // namespace

std::vector<double> spring_step_times(double time) {
    std::vector<double> times;
    if (!(time > 0.0)) return times;
    const auto steps = size_t(std::ceil(time / kSpringStep - 1e-6 / kSpringStep));
    for (size_t k = 1; k < steps; ++k) times.push_back(double(k) * kSpringStep);
    times.push_back(time);
    return times;
}

std::vector<std::optional<glm::dquat>> simulate_spring_bones(const SpringBones& bones, const std::vector<int>& parent,
                                                             const std::vector<NodeTrs>& rest,
                                                             const NodePoseAt& pose_at, double time,
                                                             const std::string& path) {
    if (bones.empty()) return {};
    const double steps = std::ceil(time / kSpringStep);
    if (steps * double(bones.joints.size() + rest.size()) > kMaxSpringWork)
        throw InputError(path, "spring bones: " + std::to_string(time) + " s is " + std::to_string(size_t(steps)) +
                                   " steps of 1/60 s for " + std::to_string(bones.joints.size()) + " joints and " +
                                   std::to_string(rest.size()) +
                                   " nodes, more than is simulated; give a shorter time or turn spring bones off");
    Simulation sim(bones, parent, rest, path);
    std::vector<NodeTrs> frame;
    double before = 0.0;
    for (double t : spring_step_times(time)) {
        frame = rest;
        sim.current_rotations(frame);
        pose_at(t, frame);
        sim.step(t - before, frame);
        before = t;
    }
    return sim.rotations();
}

}  // namespace inkshade::io
