//! Union–find: items joined into classes, each item knowing whether it runs against its
//! class's root (the sides of a B-rep that are one edge, some of them the other way round;
//! the faces that share edges, all the same way).

/// Classes of items `0..len`, with each item's direction relative to its class's root.
#[derive(Clone, Debug, Default)]
pub(crate) struct Classes {
    /// Each item's parent and whether it runs against it; a root is its own parent.
    parent: Vec<(usize, bool)>,
}

impl Classes {
    /// `n` items, each a class of its own.
    pub(crate) fn new(n: usize) -> Self {
        Self {
            parent: (0..n).map(|i| (i, false)).collect(),
        }
    }

    /// A new item, a class of its own; its index.
    pub(crate) fn add(&mut self) -> usize {
        self.parent.push((self.parent.len(), false));
        self.parent.len() - 1
    }

    /// The root of `x`'s class and whether `x` runs against it. The path walked is pointed
    /// at the root (iteratively: classes may hold a great many items).
    pub(crate) fn find(&mut self, x: usize) -> (usize, bool) {
        let (mut root, mut against) = (x, false);
        while self.parent[root].0 != root {
            against ^= self.parent[root].1;
            root = self.parent[root].0;
        }
        let (mut node, mut to_root) = (x, against);
        while node != root {
            let (next, flip) = self.parent[node];
            self.parent[node] = (root, to_root);
            to_root ^= flip;
            node = next;
        }
        (root, against)
    }

    /// Joins the classes of `a` and `b`, `b` running against `a` when `reversed`; the
    /// smaller root stays the root.
    pub(crate) fn join(&mut self, a: usize, b: usize, reversed: bool) {
        let ((ra, fa), (rb, fb)) = (self.find(a), self.find(b));
        let flip = (fa != fb) != reversed;
        if ra < rb {
            self.parent[rb] = (ra, flip);
        } else if rb < ra {
            self.parent[ra] = (rb, flip);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Classes;

    #[test]
    fn joined_items_share_a_root_and_know_their_direction() {
        let mut c = Classes::new(6);
        c.join(1, 2, true);
        c.join(2, 3, false);
        c.join(4, 3, true);
        let roots: Vec<(usize, bool)> = (0..6).map(|i| c.find(i)).collect();
        assert_eq!(roots[0], (0, false));
        assert_eq!(roots[5], (5, false));
        assert_eq!(roots[1], (1, false));
        // 2 runs against 1, 3 with 2, 4 against 3.
        assert_eq!(roots[2], (1, true));
        assert_eq!(roots[3], (1, true));
        assert_eq!(roots[4], (1, false));
    }

    #[test]
    fn a_long_chain_is_found_without_recursion() {
        let n = 1_000_000;
        let mut c = Classes::new(n);
        for i in (1..n).rev() {
            c.join(i, i - 1, true);
        }
        assert_eq!(c.find(n - 1), (0, (n - 1) % 2 == 1));
    }
}
