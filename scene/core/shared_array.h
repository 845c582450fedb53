#pragma once
// A std::vector with value semantics whose storage copies share until one of them is written (copy
// on write). The scene's vertex, index and image arrays use it, so copying a Scene (the renderer's
// snapshot, a preparation on a worker, an undo command's value) costs O(nodes and primitives), not
// O(vertices): a gizmo drag on a large mesh scene copied all vertex data per frame.
//
// Reads through a const object never copy. Any access through a non-const object that could write
// (non-const operator[], begin(), data(), push_back, edit(), ...) first gives the object storage of
// its own if the storage is shared. Shared storage is never written, so copies on other threads
// read it safely; one object is no more thread-safe than a std::vector.
#include <cstddef>
#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

namespace glint {

template <class T>
class SharedArray {
public:
    using Vector = std::vector<T>;
    using value_type = T;
    using size_type = std::size_t;
    using iterator = typename Vector::iterator;
    using const_iterator = typename Vector::const_iterator;

    SharedArray() = default;
    SharedArray(Vector values) : data_(values.empty() ? nullptr : std::make_shared<Vector>(std::move(values))) {}
    SharedArray(std::initializer_list<T> values) : SharedArray(Vector(values)) {}
    template <class It>
    SharedArray(It first, It last) : SharedArray(Vector(first, last)) {}

    SharedArray& operator=(Vector values) {
        data_ = values.empty() ? nullptr : std::make_shared<Vector>(std::move(values));
        return *this;
    }
    SharedArray& operator=(std::initializer_list<T> values) { return *this = Vector(values); }

    // --- reads (never copy) --------------------------------------------------------------------
    const Vector& vector() const { return data_ ? *data_ : none(); }
    operator const Vector&() const { return vector(); }
    std::size_t size() const { return data_ ? data_->size() : 0; }
    bool empty() const { return size() == 0; }
    const_iterator begin() const { return vector().begin(); }
    const_iterator end() const { return vector().end(); }
    const_iterator cbegin() const { return begin(); }
    const_iterator cend() const { return end(); }
    const T& operator[](std::size_t i) const { return vector()[i]; }
    const T& at(std::size_t i) const { return vector().at(i); }
    const T& front() const { return vector().front(); }
    const T& back() const { return vector().back(); }
    const T* data() const { return vector().data(); }
    // Whether two arrays share their storage (a copy not written since).
    bool sharesWith(const SharedArray& other) const { return data_ && data_ == other.data_; }

    // --- writes (storage of its own first) -----------------------------------------------------
    Vector& edit() {
        if (!data_) data_ = std::make_shared<Vector>();
        else if (data_.use_count() > 1) data_ = std::make_shared<Vector>(*data_);
        return *data_;
    }
    iterator begin() { return edit().begin(); }
    iterator end() { return edit().end(); }
    T& operator[](std::size_t i) { return edit()[i]; }
    T& at(std::size_t i) { return edit().at(i); }
    T& front() { return edit().front(); }
    T& back() { return edit().back(); }
    T* data() { return edit().data(); }
    void push_back(const T& value) { edit().push_back(value); }
    void push_back(T&& value) { edit().push_back(std::move(value)); }
    template <class... Args>
    T& emplace_back(Args&&... args) { return edit().emplace_back(std::forward<Args>(args)...); }
    void pop_back() { edit().pop_back(); }
    void clear() { data_.reset(); }
    void resize(std::size_t n) { edit().resize(n); }
    void resize(std::size_t n, const T& value) { edit().resize(n, value); }
    void reserve(std::size_t n) { edit().reserve(n); }
    void assign(std::size_t n, const T& value) { *this = Vector(n, value); }
    void assign(std::initializer_list<T> values) { *this = Vector(values); }
    template <class It>
    void assign(It first, It last) { *this = Vector(first, last); }
    template <class... Args>
    iterator insert(const_iterator at, Args&&... args) {
        const auto offset = at - vector().begin(); // `at` points into the storage edit() may replace
        Vector& v = edit();
        return v.insert(v.begin() + offset, std::forward<Args>(args)...);
    }
    iterator insert(const_iterator at, std::initializer_list<T> values) {
        const auto offset = at - vector().begin();
        Vector& v = edit();
        return v.insert(v.begin() + offset, values);
    }

    friend bool operator==(const SharedArray& a, const SharedArray& b) { return a.data_ == b.data_ || a.vector() == b.vector(); }
    friend bool operator==(const SharedArray& a, const Vector& b) { return a.vector() == b; }

private:
    static const Vector& none() {
        static const Vector nothing;
        return nothing;
    }
    std::shared_ptr<Vector> data_;
};

} // namespace glint
