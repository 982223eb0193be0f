// How the viewer calls links, hulls and obstacles: by the names the report's `scene` carries
// (cells: URDF link names, obstacle names), with the index beside them; by index alone when the
// report has no names (thesis files).

export function makeNames(scene) {
  const linkName = (link) => scene.links[link]?.name ?? null;
  const obstacleName = (obstacle) => scene.obstacles[obstacle]?.name ?? null;
  const hullName = (link, hull) => scene.links[link]?.hulls.find((h) => h.hull === hull)?.name ?? null;
  return {
    /// "forearm_link (link 3)" or "link 3".
    link(link) {
      const name = linkName(link);
      return name ? `${name} (link ${link})` : `link ${link}`;
    },
    /// The name alone when there is one (short places: the plot legend), else "link 3".
    linkShort(link) {
      return linkName(link) ?? `link ${link}`;
    },
    /// "post (obstacle 7)" or "obstacle 7".
    obstacle(obstacle) {
      const name = obstacleName(obstacle);
      return name ? `${name} (obstacle ${obstacle})` : `obstacle ${obstacle}`;
    },
    /// "link_4 hull 0 / post": an episode's or a contact's pair.
    pair(link, hull, obstacle) {
      const l = linkName(link) ?? `link ${link}`;
      const o = obstacleName(obstacle) ?? `obstacle ${obstacle}`;
      return `${l} hull ${hull} / ${o}`;
    },
    /// The hover text of a picked object (scene_builder.js userData).
    hover(data) {
      if (data.kind === 'obstacle') return this.obstacle(data.obstacle);
      const hull = hullName(data.link, data.hull);
      const suffix = hull && hull !== linkName(data.link) ? ` (${hull})` : '';
      return `${this.link(data.link)}, hull ${data.hull}${suffix}`;
    },
  };
}
